# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Choose the sheet (A4 or A3 landscape), the scale and the view positions of a part drawing.

Pure Python, so it runs both inside FreeCAD and in the project's tests. Page coordinates are millimetres
with the origin at the sheet's bottom-left corner and y up (how TechDraw places views).

First-angle arrangement (ISO 128-30): the front view at the top left, the view from the left to its
right, the view from above below it; the isometric view goes wherever it fits, at the same scale or, when it
does not fit there, at up to two standard scales smaller (it is not dimensioned). The notes sit in a strip
above the title block."""
from __future__ import annotations

from dataclasses import dataclass

GAP = 6.0          # between the boxes of two views (each box already includes its dimensions)
INSET = 4.0        # between the drawing border and any view box
NOTES_HEIGHT = 26.0   # the notes strip's height unless the notes need another (notes_block)
# ISO 5455 scales, largest first
SCALES = (10.0, 5.0, 2.0, 1.0, 0.5, 0.2, 0.1)
ISO_STEPS = 2      # how many standard scales the isometric view may drop below the others


@dataclass(frozen=True)
class Sheet:
    name: str
    template: str       # file in FreeCAD's Mod/TechDraw/Templates
    width: float
    height: float
    border: tuple       # x0, y0, x1, y1 of the drawing frame
    title_block: tuple  # x0, y0, x1, y1


# Frames and title blocks as drawn in FreeCAD 0.20's ISO 7200 templates (read from the SVG files, y flipped).
SHEETS = (
    Sheet("A4", "A4_Landscape_ISO7200_Pep.svg", 297.0, 210.0, (7.0, 7.0, 290.0, 195.0), (150.0, 7.0, 290.0, 41.0)),
    Sheet("A3", "A3_Landscape_ISO7200_Pep.svg", 420.0, 297.0, (22.0, 11.0, 409.0, 286.0), (269.0, 11.0, 409.0, 45.0)),
)


@dataclass(frozen=True)
class ViewBox:
    """A view's drawn extent around its centre in model mm (unscaled) and the room its dimensions need on each
    side in page mm: the linear dimensions' stacks (independent of the scale) and its texts (which depend on it)."""
    xmin: float
    xmax: float
    ymin: float
    ymax: float
    left: float = 0.0
    right: float = 0.0
    below: float = 0.0
    above: float = 0.0
    # scale -> (left, right, below, above): page mm its texts reach past the outline at that scale (diameter texts
    # sit at the end of leaders from circles, which move with the scale)
    texts: object = None

    def extents(self, scale: float) -> tuple:
        """(left, right, below, above) distances from the view centre to the edge of its box, page mm."""
        tl, tr, tb, ta = self.texts(scale) if self.texts is not None else (0.0, 0.0, 0.0, 0.0)
        return (-self.xmin * scale + max(self.left, tl), self.xmax * scale + max(self.right, tr),
                -self.ymin * scale + max(self.below, tb), self.ymax * scale + max(self.above, ta))


@dataclass(frozen=True)
class Layout:
    sheet: Sheet
    scale: float
    centres: dict       # view name -> (x, y) page mm
    boxes: dict         # view name -> (x0, y0, x1, y1) page mm, dimensions included
    notes: tuple        # x0, y0, x1, y1 of the notes strip
    iso_scale: float = 0.0   # the isometric view's


def scale_label(scale: float) -> str:
    return f"{scale:g}:1" if scale >= 1 else f"1:{1 / scale:g}"


def _overlap(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _inside(box, frame) -> bool:
    return box[0] >= frame[0] - 1e-9 and box[1] >= frame[1] - 1e-9 and box[2] <= frame[2] + 1e-9 and box[3] <= frame[3] + 1e-9


def _arrange(sheet: Sheet, scale: float, views: dict, spread: float, notes_height: float):
    """Principal views in the first-angle pattern; spread (0..1) shares out the room left over."""
    x0, y0, x1, y1 = sheet.border
    frame = (x0 + INSET, y0 + INSET, x1 - INSET, y1 - INSET)
    tb = sheet.title_block
    notes = (tb[0], tb[3], tb[2], tb[3] + notes_height)
    obstacle = (tb[0] - GAP, tb[1], tb[2], notes[3] + GAP)
    fl, fr, fb, fa = views["front"].extents(scale)
    sl, sr, sb, sa = views["left"].extents(scale)
    tl, tr, tb_, ta = views["top"].extents(scale)
    il, ir, _, _ = views["iso"].extents(scale)      # room kept for it when sharing out the slack
    col1_l, col1_r = max(fl, tl), max(fr, tr)
    row1_b, row1_a = max(fb, sb), max(fa, sa)
    width = col1_l + col1_r + GAP + sl + sr
    height = row1_a + row1_b + GAP + ta + tb_
    slack_x = max(0.0, (frame[2] - frame[0]) - width - GAP - il - ir) * spread
    slack_y = max(0.0, (frame[3] - frame[1]) - height) * spread
    fx = frame[0] + slack_x / 4 + col1_l
    fy = frame[3] - slack_y / 4 - row1_a
    sx = fx + col1_r + GAP + slack_x / 4 + sl
    ty = fy - row1_b - GAP - slack_y / 4 - ta
    centres = {"front": (fx, fy), "left": (sx, fy), "top": (fx, ty)}
    boxes = {}
    for name, (cx, cy) in centres.items():
        l_, r_, b_, a_ = views[name].extents(scale)
        boxes[name] = (cx - l_, cy - b_, cx + r_, cy + a_)
    for box in boxes.values():
        if not _inside(box, frame) or _overlap(box, obstacle):
            return None
    # The isometric view: the first free spot, most open corner first, at the largest scale that finds one.
    for iso_scale in [s for s in SCALES if s <= scale][:ISO_STEPS + 1]:
        jl, jr, jb, ja = views["iso"].extents(iso_scale)
        w, h = jl + jr, jb + ja
        spots = [(frame[2] - w, frame[3] - h),                          # top right
                 (frame[2] - w, obstacle[3] + GAP),                     # right, above the notes
                 (boxes["left"][0], boxes["left"][1] - GAP - h),        # under the left view
                 (boxes["left"][2] + GAP, frame[3] - h),                # right of the left view
                 (boxes["top"][2] + GAP, boxes["top"][1])]              # right of the top view
        for sx0, sy0 in spots:
            box = (sx0, sy0, sx0 + w, sy0 + h)
            free = not any(_overlap(box, b) for b in boxes.values())
            if free and _inside(box, frame) and not _overlap(box, obstacle):
                boxes["iso"] = box
                centres["iso"] = (sx0 + jl, sy0 + jb)
                return Layout(sheet, scale, centres, boxes, notes, iso_scale)
    return None


def fit(sheet: Sheet, scale: float, views: dict, notes_height: float = NOTES_HEIGHT) -> Layout | None:
    """The layout of the four views (front, left, top, iso) at this scale on this sheet, or None."""
    for spread in (1.0, 0.5, 0.0):
        layout = _arrange(sheet, scale, views, spread, notes_height)
        if layout is not None:
            return layout
    return None


def choose(views: dict, notes_height: float = NOTES_HEIGHT) -> Layout:
    """A4 at the largest standard scale that fits; A3 only when A4 would need a reduced scale and A3 allows a
    larger one."""
    best = {}
    for sheet in SHEETS:
        for scale in SCALES:
            layout = fit(sheet, scale, views, notes_height)
            if layout is not None:
                best[sheet.name] = layout
                break
    a4, a3 = best.get("A4"), best.get("A3")
    if a4 and (a4.scale >= 1.0 or not a3 or a3.scale <= a4.scale):
        return a4
    if a3:
        return a3
    raise ValueError(f"the views do not fit on A3 even at {scale_label(SCALES[-1])}")
