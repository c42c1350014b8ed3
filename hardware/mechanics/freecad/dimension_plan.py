# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Which dimensions a view of a machined part gets, from the view's own projected geometry.

Pure Python (runs inside FreeCAD and in the tests). Coordinates are the view's model millimetres
(unscaled, centred on the view, y up), as TechDraw's DrawViewPart.getVertexByIndex reports them.

Per view:
- the overall extent across and up, between the outermost vertices (or, where the outline is a curve
  with no vertex at its extreme, the point where the curve reaches it). A round outline is given by
  its diameter instead;
- one diameter per size and callout of full circle (holes, bores, shafts), "N× " when several holes share it:
  visible circles, and hidden ones that are holes (a hole that opens away from the view). A hole's diameter
  carries its callout (hole_callouts: depth, thread, counterbore);
- the position of every circle centre from the datum edges (the left and bottom extremes; the centre
  of a round outline), one baseline dimension per distinct coordinate.
Horizontal dimensions stack below the view, vertical ones left of it, the overall extent outermost."""
from __future__ import annotations

import copy
import math
from dataclasses import dataclass, field

TOL = 1e-3          # mm: two coordinates are the same
FIRST = 8.0         # page mm from the view's edge to the first dimension line
PITCH = 9.0         # page mm between stacked dimension lines (clear of the inner extension lines' overshoot)
TEXT = 4.0          # page mm for the text beyond the last line
LEADER = 9.0        # page mm from a circle to the end of its diameter's reference line
LEADER_STEPS = (0.0, 8.0, 16.0)   # longer leaders place_labels may use when the short one's text would collide
# A diameter is drawn in TechDraw's "ISO Referencing" style: a leader from the circle to a horizontal reference
# line, the text on it. TechDraw 0.20 centres the text across on DrawViewDimension.X and puts the top of its
# box LABEL_ABOVE above Y and its baseline LABEL_BELOW below (osifont, 5 mm, as measured in its SVG export);
# the text is 2.3 to 2.7 mm per character plus a margin.
CHAR_WIDTH = 2.8    # page mm per character, generous: keeps labels apart
LABEL_MARGIN = 2.0  # page mm added to a text's width
LABEL_ABOVE = 3.0
LABEL_BELOW = 5.0


@dataclass(frozen=True)
class Circle:
    edge: int            # TechDraw edge index ("EdgeN")
    x: float
    y: float
    r: float
    callout: object = None   # hole_callouts.Callout when the circle is a hole seen along its axis


@dataclass(frozen=True)
class Extreme:
    coord: float         # exact extreme of the visible geometry on this side
    point: tuple         # a point of the geometry where it is reached


@dataclass
class Dim:
    kind: str            # "extent", "position" or "diameter"
    type: str            # TechDraw DrawViewDimension.Type
    refs: list           # ("vertex", index) | ("point", (x, y)) | ("edge", index)
    value: float         # what the dimension must measure, model mm
    side: str            # "below", "left" or "leader"
    row: int = 0
    anchor: tuple = (0.0, 0.0)    # model mm: the midpoint of the measured span, or the circle centre
    direction: tuple = (0.0, 0.0)  # leader direction (unit) for diameters
    radius: float = 0.0
    prefix: str = ""     # "4× "
    symbol: str = "⌀"    # diameters: before the number ("⌀", "M", "⌴⌀")
    suffix: str = ""     # diameters: after it (" ↧8")
    axis: str = ""       # model axis the dimension measures ("X", "Y", "Z"), "" for diameters
    choices: list = field(default_factory=list)   # diameters: every circle of this size, as Circle
    extra: float = 0.0   # diameters: page mm the leader runs beyond LEADER, to clear the other texts

    def text_position(self, box_xmin: float, box_ymin: float, scale: float) -> tuple:
        """Page mm relative to the view centre (DrawViewDimension.X/Y)."""
        if self.side == "below":
            return self.anchor[0] * scale, box_ymin * scale - FIRST - self.row * PITCH
        if self.side == "left":
            return box_xmin * scale - FIRST - self.row * PITCH, self.anchor[1] * scale
        # the leader's end, then the text beside it, away from the circle
        reach = self.radius * scale + LEADER + self.extra
        half = label_width(self) / 2
        return (self.anchor[0] * scale + self.direction[0] * reach + math.copysign(half, self.direction[0]),
                self.anchor[1] * scale + self.direction[1] * reach)


@dataclass
class Plan:
    dims: list = field(default_factory=list)
    below: float = 0.0   # page mm the dimensions need on each side of the view
    left: float = 0.0
    above: float = 0.0
    right: float = 0.0


def _vertex_on(vertices, pred, key):
    found = [i for i, v in enumerate(vertices) if pred(v)]
    return min(found, key=lambda i: key(vertices[i])) if found else None


def _ref(vertices, point):
    for i, v in enumerate(vertices):
        if abs(v[0] - point[0]) < TOL and abs(v[1] - point[1]) < TOL:
            return ("vertex", i)
    return ("point", tuple(point))


def _outline_circle(circles, ext):
    """The full circle that forms the whole outline (a round part seen along its axis), if any."""
    for c in sorted(circles, key=lambda c: -c.r):
        if (abs(c.x - c.r - ext["xmin"].coord) < TOL and abs(c.x + c.r - ext["xmax"].coord) < TOL and
                abs(c.y - c.r - ext["ymin"].coord) < TOL and abs(c.y + c.r - ext["ymax"].coord) < TOL):
            return c
    return None


def _kind(c: Circle) -> tuple:
    """What a circle's diameter says besides the number: (symbol, suffix)."""
    return (c.callout.symbol, c.callout.suffix) if c.callout is not None else ("⌀", "")


def _unique(values):
    out = []
    for v in sorted(values):
        if not out or abs(v - out[-1]) > 0.01:
            out.append(v)
    return out


def plan(vertices: list, circles: list, extremes: dict, axes: tuple = ("", "")) -> Plan:
    """vertices: [(x, y)] in TechDraw's vertex order; circles: visible full circles; extremes: xmin, xmax,
    ymin, ymax -> Extreme; axes: the model axes shown across and up."""
    ext = extremes
    # Holes per callout, counted before coincident circles merge (both ends of a bar's holes are one circle).
    holes: dict = {}
    for c in circles:
        if c.callout is not None:
            holes.setdefault((round(2 * c.r, 2), _kind(c)), set()).update(c.callout.holes)
    unique: dict = {}
    for c in circles:     # the first of coincident circles stays: visible ones come first
        unique.setdefault((round(c.x, 4), round(c.y, 4), round(c.r, 4), _kind(c)), c)
    circles = list(unique.values())
    outline = _outline_circle(circles, ext)
    result = Plan()
    below, left = [], []

    def on_side(coord_index, value):
        return lambda v: abs(v[coord_index] - value) < TOL

    if outline is None:
        # Outermost vertices, the ones nearest the dimension line (lowest for "below", leftmost for "left").
        x_refs = []
        for side in ("xmin", "xmax"):
            i = _vertex_on(vertices, on_side(0, ext[side].coord), key=lambda v: v[1])
            x_refs.append(("vertex", i) if i is not None else ("point", ext[side].point))
        y_refs = []
        for side in ("ymin", "ymax"):
            i = _vertex_on(vertices, on_side(1, ext[side].coord), key=lambda v: v[0])
            y_refs.append(("vertex", i) if i is not None else ("point", ext[side].point))
        datum_x, datum_y = x_refs[0], y_refs[0]
        datum = (ext["xmin"].coord, ext["ymin"].coord)
        width = ext["xmax"].coord - ext["xmin"].coord
        height = ext["ymax"].coord - ext["ymin"].coord
        mid = ((ext["xmin"].coord + ext["xmax"].coord) / 2, (ext["ymin"].coord + ext["ymax"].coord) / 2)
        extent_x = Dim("extent", "DistanceX", x_refs, width, "below", anchor=mid, axis=axes[0])
        extent_y = Dim("extent", "DistanceY", y_refs, height, "left", anchor=mid, axis=axes[1])
    else:
        centre = _ref(vertices, (outline.x, outline.y))
        datum_x = datum_y = centre
        datum = (outline.x, outline.y)
        extent_x = extent_y = None

    for x in _unique(c.x for c in circles):
        if abs(x - datum[0]) > 0.01:
            c = next(c for c in circles if abs(c.x - x) <= 0.01)
            below.append(Dim("position", "DistanceX", [datum_x, _ref(vertices, (c.x, c.y))], abs(c.x - datum[0]),
                             "below", anchor=((c.x + datum[0]) / 2, 0.0), axis=axes[0]))
    for y in _unique(c.y for c in circles):
        if abs(y - datum[1]) > 0.01:
            c = next(c for c in circles if abs(c.y - y) <= 0.01)
            left.append(Dim("position", "DistanceY", [datum_y, _ref(vertices, (c.x, c.y))], abs(c.y - datum[1]),
                            "left", anchor=(0.0, (c.y + datum[1]) / 2), axis=axes[1]))
    below.sort(key=lambda d: d.value)
    left.sort(key=lambda d: d.value)
    if extent_x is not None:
        below.append(extent_x)
        left.append(extent_y)
    for row, d in enumerate(below):
        d.row = row
    for row, d in enumerate(left):
        d.row = row

    # One diameter per size and callout; place_labels picks the circle and the side that keep the texts apart.
    for d in _unique(2 * c.r for c in circles):
        for kind in sorted({_kind(c) for c in circles if abs(2 * c.r - d) <= 0.01}):
            group = sorted((c for c in circles if abs(2 * c.r - d) <= 0.01 and _kind(c) == kind),
                           key=lambda c: (-(c.x ** 2 + c.y ** 2), -c.y, -c.x))
            c = group[0]
            count = len(holes.get((round(d, 2), kind), ())) + sum(g.callout is None for g in group)
            prefix = f"{count}× " if count > 1 else ""
            result.dims.append(Dim("diameter", "Diameter", [("edge", c.edge)], 2 * c.r, "leader", anchor=(c.x, c.y),
                                   direction=(0.7071 if c.x >= 0 else -0.7071, 0.7071), radius=c.r, prefix=prefix,
                                   symbol=kind[0], suffix=kind[1], choices=group))
    result.dims = below + left + result.dims
    # The diameter texts' room depends on the scale (label_room); these are the linear dimensions' stacks.
    result.below = FIRST + max(len(below) - 1, 0) * PITCH + TEXT if below else 0.0
    result.left = FIRST + max(len(left) - 1, 0) * PITCH + TEXT if left else 0.0
    return result


def _chars(d: Dim) -> int:
    return len(d.prefix) + len(d.symbol) + len(f"{d.value:.2f}".rstrip("0").rstrip(".")) + len(d.suffix)


def label_width(d: Dim) -> float:
    """Page mm a diameter's text is wide."""
    return _chars(d) * CHAR_WIDTH + LABEL_MARGIN


def _label_box(d: Dim, scale: float) -> tuple:
    """Page-mm box around a diameter's text (horizontal, on its reference line), with 1 mm around."""
    x, y = d.text_position(0.0, 0.0, scale)
    half = label_width(d) / 2 + 1.0
    return (x - half, y - LABEL_BELOW - 1.0, x + half, y + LABEL_ABOVE + 1.0)


def _overlap(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def place_labels(plan: Plan, scale: float, extremes: dict | None = None) -> None:
    """Give each diameter a circle of its size, a leader direction and length. The text should not overlap
    another diameter text, then no circle, then should stay out of the linear dimensions below and left of the
    view, then out of the view itself; then the shortest leader; among equals, up and outwards from the circle
    farthest out comes first."""
    zones = []
    if extremes is not None:
        x0, x1 = extremes["xmin"].coord * scale, extremes["xmax"].coord * scale
        y0, y1 = extremes["ymin"].coord * scale, extremes["ymax"].coord * scale
        zones = [(10, (x0 - plan.left, y0 - plan.below, x1, y0)),     # the stack of horizontal dimensions
                 (10, (x0 - plan.left, y0, x0, y1)),                  # the stack of vertical dimensions
                 (1, (x0, y0, x1, y1))]                               # the part itself
    # the circles themselves: a text over a hole hides it
    circles = {(c.x, c.y, c.r) for d in plan.dims if d.kind == "diameter" for c in d.choices}
    zones += [(20, ((x - r) * scale, (y - r) * scale, (x + r) * scale, (y + r) * scale)) for x, y, r in circles]
    placed = []
    for d in (d for d in plan.dims if d.kind == "diameter"):
        best = None
        for order, c in enumerate(d.choices or [Circle(d.refs[0][1], d.anchor[0], d.anchor[1], d.radius)]):
            out = 1.0 if c.x >= 0 else -1.0
            for turn, (sx, sy) in enumerate(((out, 1.0), (-out, 1.0), (out, -1.0), (-out, -1.0))):
                for step, extra in enumerate(LEADER_STEPS):
                    d.refs, d.anchor, d.direction = [("edge", c.edge)], (c.x, c.y), (sx * 0.7071, sy * 0.7071)
                    d.extra = extra
                    box = _label_box(d, scale)
                    cost = (100 * sum(_overlap(box, b) for b in placed) +
                            sum(w for w, zone in zones if _overlap(box, zone)), step, order + turn)
                    if best is None or cost < best[0]:
                        best = (cost, d.refs, d.anchor, d.direction, extra, box)
        _, d.refs, d.anchor, d.direction, d.extra, box = best
        placed.append(box)


def label_room(plan: Plan, scale: float, extremes: dict) -> tuple:
    """(left, right, below, above): page mm the diameter texts reach past the view's outline at this scale, placed
    as place_labels will place them. The plan itself is left as it is."""
    trial = copy.deepcopy(plan)
    place_labels(trial, scale, extremes)
    x0, x1 = extremes["xmin"].coord * scale, extremes["xmax"].coord * scale
    y0, y1 = extremes["ymin"].coord * scale, extremes["ymax"].coord * scale
    boxes = [_label_box(d, scale) for d in trial.dims if d.kind == "diameter"]
    return (max([x0 - b[0] for b in boxes] + [0.0]), max([b[2] - x1 for b in boxes] + [0.0]),
            max([y0 - b[1] for b in boxes] + [0.0]), max([b[3] - y1 for b in boxes] + [0.0]))
