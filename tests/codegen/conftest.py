# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
import sys
import types
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "codegen"))

# robogene.dev is tested from this source tree. The compiled core (Bottle, for the RPC tests) comes
# from the installed package when there is one (`make python`); otherwise a bare package stands in,
# which is enough for everything but the RPC tests.
_SOURCE = str(ROOT / "runtime" / "python" / "robogene")
try:
    import robogene
except ImportError:
    robogene = types.ModuleType("robogene")
    robogene.__path__ = []
    sys.modules["robogene"] = robogene
if _SOURCE not in robogene.__path__:
    robogene.__path__.insert(0, _SOURCE)
