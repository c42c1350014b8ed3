# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""`make python` rebuilds the extension when any source it is built from changes: the runtime, and also the
drivers and the boards' control core that the extension links (an edit there once left a stale module)."""
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

SOURCES = [
    "runtime/ports/src/port.cpp",
    "drivers/can/src/frame.cpp",
    "hardware/electronics/firmware/core/rg_board.c",
]


@pytest.mark.parametrize("source", SOURCES)
def test_an_edited_source_rebuilds_the_extension(source):
    assert (ROOT / source).is_file(), f"{source} moved: name another source of the same part of the tree"
    shown = subprocess.run(["make", "-n", "--no-print-directory", "-W", source, "python"],
                           cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert shown.returncode == 0, shown.stderr
    assert "pip install" in shown.stdout, f"an edit of {source} would not rebuild the extension"
