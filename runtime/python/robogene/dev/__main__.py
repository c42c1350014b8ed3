# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""python -m robogene.dev: serve a Python device on the network (robogene.dev.cli)."""
import sys

from .cli import main

sys.exit(main())
