# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Which dimensions a view of a machined part gets, from the view's own projected geometry.

Pure Python (runs inside FreeCAD and in the tests). Coordinates are the view's model millimetres
(unscaled, centred on the view, y up), as TechDraw's DrawViewPart.getVertexByIndex reports them.

Per view:
- the overall extent across and up, between the outermost vertices (or, where the outline is a curve
  with no vertex at its extreme, the point where the curve reaches it). A round outline is given by
  its diameter instead;
- one diameter per size of visible full circle (holes, bores, shafts), "N× " when several share it;
- the position of every circle centre from the datum edges (the left and bottom extremes; the centre
  of a round outline), one baseline dimension per distinct coordinate.
Horizontal dimensions stack below the view, vertical ones left of it, the overall extent outermost."""
from __future__ import annotations

from dataclasses import dataclass, field

TOL = 1e-3          # mm: two coordinates are the same
FIRST = 8.0         # page mm from the view's edge to the first dimension line
PITCH = 9.0         # page mm between stacked dimension lines (clear of the inner extension lines' overshoot)
TEXT = 4.0          # page mm for the text beyond the last line
LEADER = 9.0        # page mm from a circle to its diameter text
LABEL_ROOM = 14.0   # page mm around the view for diameter texts
CHAR_WIDTH = 3.0    # page mm per character of a 3.5 mm dimension text, generous: keeps labels apart
TEXT_HEIGHT = 4.5


@dataclass(frozen=True)
class Circle:
    edge: int            # TechDraw edge index ("EdgeN")
    x: float
    y: float
    r: float


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
    prefix: str = ""
    axis: str = ""       # model axis the dimension measures ("X", "Y", "Z"), "" for diameters
    choices: list = field(default_factory=list)   # diameters: every circle of this size, as Circle

    def text_position(self, box_xmin: float, box_ymin: float, scale: float) -> tuple:
        """Page mm relative to the view centre (DrawViewDimension.X/Y)."""
        if self.side == "below":
            return self.anchor[0] * scale, box_ymin * scale - FIRST - self.row * PITCH
        if self.side == "left":
            return box_xmin * scale - FIRST - self.row * PITCH, self.anchor[1] * scale
        reach = self.radius * scale + LEADER
        return (self.anchor[0] * scale + self.direction[0] * reach,
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
    circles = list({(round(c.x, 4), round(c.y, 4), round(c.r, 4)): c for c in circles}.values())
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

    # One diameter per size; place_labels picks the circle and the side that keep the texts apart.
    for d in _unique(2 * c.r for c in circles):
        group = sorted((c for c in circles if abs(2 * c.r - d) <= 0.01), key=lambda c: (-(c.x ** 2 + c.y ** 2), -c.y, -c.x))
        c = group[0]
        prefix = f"{len(group)}× " if len(group) > 1 else ""
        result.dims.append(Dim("diameter", "Diameter", [("edge", c.edge)], 2 * c.r, "leader", anchor=(c.x, c.y),
                               direction=(0.7071 if c.x >= 0 else -0.7071, 0.7071), radius=c.r, prefix=prefix,
                               choices=group))
    result.dims = below + left + result.dims
    result.below = FIRST + max(len(below) - 1, 0) * PITCH + TEXT if below else 0.0
    result.left = FIRST + max(len(left) - 1, 0) * PITCH + TEXT if left else 0.0
    result.above = result.right = LABEL_ROOM if circles else 0.0
    if circles:
        result.left = max(result.left, LABEL_ROOM)
    return result


def _label_box(d: Dim, scale: float) -> tuple:
    """Page-mm box around a diameter text. TechDraw writes it along the 45° leader, so the box bounds the
    turned text."""
    x, y = d.text_position(0.0, 0.0, scale)
    length = (len(d.prefix) + len(f"{d.value:.2f}".rstrip("0").rstrip(".")) + 1) * CHAR_WIDTH
    half = (length + TEXT_HEIGHT) * 0.7071 / 2 + 1.0
    return (x - half, y - half, x + half, y + half)


def _overlap(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def place_labels(plan: Plan, scale: float, extremes: dict | None = None) -> None:
    """Give each diameter a circle of its size and a leader direction. The text should not overlap another
    diameter text, then should stay out of the linear dimensions below and left of the view, then out of
    the view itself; among equals, up and outwards from the circle farthest out comes first."""
    zones = []
    if extremes is not None:
        x0, x1 = extremes["xmin"].coord * scale, extremes["xmax"].coord * scale
        y0, y1 = extremes["ymin"].coord * scale, extremes["ymax"].coord * scale
        zones = [(10, (x0 - plan.left, y0 - plan.below, x1, y0)),     # the stack of horizontal dimensions
                 (10, (x0 - plan.left, y0, x0, y1)),                  # the stack of vertical dimensions
                 (1, (x0, y0, x1, y1))]                               # the part itself
    placed = []
    for d in (d for d in plan.dims if d.kind == "diameter"):
        best = None
        for order, c in enumerate(d.choices or [Circle(d.refs[0][1], d.anchor[0], d.anchor[1], d.radius)]):
            out = 1.0 if c.x >= 0 else -1.0
            for turn, (sx, sy) in enumerate(((out, 1.0), (-out, 1.0), (out, -1.0), (-out, -1.0))):
                d.refs, d.anchor, d.direction = [("edge", c.edge)], (c.x, c.y), (sx * 0.7071, sy * 0.7071)
                box = _label_box(d, scale)
                cost = (100 * sum(_overlap(box, b) for b in placed) +
                        sum(w for w, zone in zones if _overlap(box, zone)), order + turn)
                if best is None or cost < best[0]:
                    best = (cost, d.refs, d.anchor, d.direction, box)
        _, d.refs, d.anchor, d.direction, box = best
        placed.append(box)
