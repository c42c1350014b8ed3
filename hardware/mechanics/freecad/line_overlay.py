# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The lines of a view, redrawn at ISO 128-20 widths, as an SVG symbol laid over the view.

FreeCAD 0.20's TechDraw exports every edge of a view as a hairline (PDF line width 0) whatever the view's
LineWidth, and its dashed hidden lines with a dash of 4 x that hairline (0.4 mm in the SVG, 0.1 mm in the PDF),
which prints as a solid line. No preference changes that pen. A TechDraw symbol is drawn with the widths and
dashes its SVG gives, in both exports, so each view gets one: visible lines wide, hidden lines narrow and
dashed. TechDraw's own hidden lines are switched off (draw_parts.py), its visible hairlines lie under ours.

Pure Python: the view's edges come in as polylines in page mm, relative to the view's centre, y down."""
from __future__ import annotations

import math

VISIBLE_WIDTH = 0.5          # mm, ISO 128-20 line group 0.5 (A4 to A3): wide
HIDDEN_WIDTH = 0.25          # narrow
# Dash and gap, mm. Shorter than ISO 128-20's 12 x / 3 x the width, so that the hidden edges of the 2 to 4 mm
# holes and counterbores still show a gap.
HIDDEN_DASH = (1.5, 0.5)
# TechDraw 0.20 scales a symbol's SVG by 3.78 px per mm (QGIViewSymbol); Qt sizes an SVG in whole pixels, so
# the symbol is made a whole number of pixels wide and high, and the view box is set to match exactly.
PX_PER_MM = 3.78
# SVG user units per mm inside the symbol. Qt's SVG writer scales a dash by the integer part of the line width,
# so every width must be at least one unit.
UNITS = 100.0
MARGIN = 1.0                 # mm around the outermost line


def _path(polylines) -> str:
    return " ".join("M" + " L".join(f"{x * UNITS:.1f},{y * UNITS:.1f}" for x, y in line)
                    for line in polylines if len(line) >= 2)


def svg(visible: list, hidden: list) -> str:
    """The symbol for a view: visible and hidden are lists of polylines [(x, y), ...] in page mm."""
    points = [p for line in list(visible) + list(hidden) for p in line]
    if not points:
        raise ValueError("a view without lines")
    half_w = math.ceil((max(abs(x) for x, _ in points) + MARGIN) * PX_PER_MM)
    half_h = math.ceil((max(abs(y) for _, y in points) + MARGIN) * PX_PER_MM)
    w, h = half_w / PX_PER_MM * UNITS, half_h / PX_PER_MM * UNITS
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{2 * half_w}" height="{2 * half_h}" '
           f'viewBox="{-w:.4f} {-h:.4f} {2 * w:.4f} {2 * h:.4f}">']
    if hidden:
        out.append(f'<path fill="none" stroke="#000" stroke-width="{HIDDEN_WIDTH * UNITS:g}" stroke-linecap="butt" '
                   f'stroke-dasharray="{HIDDEN_DASH[0] * UNITS:g},{HIDDEN_DASH[1] * UNITS:g}" d="{_path(hidden)}"/>')
    if visible:
        out.append(f'<path fill="none" stroke="#000" stroke-width="{VISIBLE_WIDTH * UNITS:g}" stroke-linecap="round" '
                   f'stroke-linejoin="round" d="{_path(visible)}"/>')
    out.append("</svg>")
    return "".join(out)
