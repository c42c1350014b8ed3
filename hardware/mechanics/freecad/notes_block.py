# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The notes above the title block, wrapped to the strip they sit in, and the height they need, so that the
layout keeps the views clear of them (a part's note is often longer than the strip is wide).

Pure Python. Widths are estimated as for the title block: EM text heights per character, more than TechDraw's
osifont needs."""
from __future__ import annotations

import textwrap

EM = 0.6            # assumed width of a character, in text heights
LINE_PITCH = 1.33   # baseline to baseline, in text heights, as TechDraw 0.20 spaces an annotation's lines
MARGIN = 2.0        # mm above and below the block


def wrap(lines: list, width: float, size: float) -> list:
    """Each line broken at spaces (or inside a word too long) to fit width mm at text height size."""
    chars = max(1, int(width / (EM * size)))
    return [part for line in lines for part in (textwrap.wrap(line, chars) or [""])]


def height(count: int, size: float) -> float:
    """mm the block of count lines needs."""
    return count * LINE_PITCH * size + 2 * MARGIN
