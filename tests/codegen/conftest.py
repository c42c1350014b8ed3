# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "codegen"))

# robogene's Python sources are tested from this source tree, over the compiled core of the
# installed package (`make python`, which test-codegen builds first): robogene.dev is the bound C++
# device layer.
_SOURCE = str(ROOT / "runtime" / "python" / "robogene")
import robogene  # noqa: E402

if _SOURCE not in robogene.__path__:
    robogene.__path__.insert(0, _SOURCE)
