# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""A progress display for the long fabrication steps: a live bar on a terminal, plain lines in a log."""
from __future__ import annotations

import sys
import time


class Progress:
    def __init__(self, stream=None):
        self.stream = stream or sys.stderr
        self.tty = self.stream.isatty()
        self.start = time.monotonic()

    def step(self, stage: str, index: int, total: int, item: str, note: str = "") -> None:
        elapsed = time.monotonic() - self.start
        width = 24
        filled = int(width * (index + 1) / max(total, 1))
        bar = "#" * filled + "." * (width - filled)
        line = f"[{elapsed:6.1f}s] {stage:<10} [{bar}] {index + 1:>3}/{total:<3} {item} {note}".rstrip()
        if self.tty:
            self.stream.write("\r\033[K" + line[:150])
            if index + 1 == total:
                self.stream.write("\n")
        else:
            self.stream.write(line + "\n")
        self.stream.flush()

    def note(self, text: str) -> None:
        elapsed = time.monotonic() - self.start
        self.stream.write(f"[{elapsed:6.1f}s] {text}\n")
        self.stream.flush()
