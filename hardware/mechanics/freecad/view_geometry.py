# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Read a computed TechDraw DrawViewPart back as plain data for dimension_plan: its vertices, its visible
full circles and the exact extremes of its visible edges. Runs inside FreeCAD.

TechDraw reports view geometry in model millimetres, centred on the view, y up, whatever the scale."""
from __future__ import annotations

import math

import FreeCAD
import Part

from dimension_plan import Circle, Extreme

FAR = 1.0e4
DEFLECTION = 0.01   # page mm: how far a drawn polyline may stray from its curve


def _indexed(getter):
    items, i = [], 0
    while True:
        try:
            items.append(getter(i))
        except Exception:   # TechDraw raises a generic error past the last index
            return items
        i += 1


def vertices(view) -> list:
    return [(v.Point.x, v.Point.y) for v in _indexed(view.getVertexByIndex)]


def edges(view) -> list:
    return _indexed(view.getEdgeByIndex)


def _same(edge, shown, scale: float) -> bool:
    """getVisibleEdges reports edges scaled and with y pointing down (page orientation)."""
    a, b = edge.BoundBox, shown.BoundBox
    return (abs(edge.Length * scale - shown.Length) < 1e-6 and
            abs(a.XMin * scale - b.XMin) < 1e-6 and abs(a.XMax * scale - b.XMax) < 1e-6 and
            abs(-a.YMax * scale - b.YMin) < 1e-6 and abs(-a.YMin * scale - b.YMax) < 1e-6)


def visible_edges(view) -> list:
    """(index, edge) of the visible edges. getEdgeByIndex lists visible lines first, then hidden ones;
    each visible one is checked against getVisibleEdges rather than trusting that order."""
    shown = view.getVisibleEdges()
    scale = view.Scale
    out = []
    for i, e in enumerate(edges(view)[:len(shown)]):
        if not _same(e, shown[i], scale):
            raise RuntimeError(f"{view.Name}: edge {i} is not the {i}th visible edge; TechDraw's edge order changed")
        out.append((i, e))
    return out


def hidden_edges(view, visible_count: int) -> list:
    """(index, edge) of the hidden edges: TechDraw lists them after the visible ones."""
    return [(i, e) for i, e in enumerate(edges(view)) if i >= visible_count]


def full_circles(visible) -> list:
    """Edges (index, edge) that are whole circles (a hole, bore or shaft seen along its axis)."""
    out = []
    for i, e in visible:
        if isinstance(e.Curve, Part.Circle) and abs(abs(e.LastParameter - e.FirstParameter) - 2 * math.pi) < 1e-6:
            c = e.Curve.Center
            out.append(Circle(i, c.x, c.y, e.Curve.Radius))
    return out


def extremes(visible) -> dict:
    """The exact extremes of the visible geometry on each side, and a point where each is reached. Edge
    bounding boxes are not used for the value: a curve's box may include its control polygon."""
    shapes = [e for _, e in visible]
    if not shapes:
        raise RuntimeError("the view has no visible edges")
    out = {}
    probes = {"xmin": ((-FAR, -FAR, 0), (-FAR, FAR, 0), 0, 1), "xmax": ((FAR, -FAR, 0), (FAR, FAR, 0), 0, -1),
              "ymin": ((-FAR, -FAR, 0), (FAR, -FAR, 0), 1, 1), "ymax": ((-FAR, FAR, 0), (FAR, FAR, 0), 1, -1)}
    for side, (a, b, axis, sign) in probes.items():
        line = Part.makeLine(FreeCAD.Vector(*a), FreeCAD.Vector(*b))
        best = None
        for e in shapes:
            dist, pairs, _ = e.distToShape(line)
            if best is None or dist < best[0] - 1e-9:
                best = (dist, pairs[0][0])
        dist, point = best
        coord = a[axis] + sign * dist
        out[side] = Extreme(coord, (point.x, point.y))
    return out


def polylines(shown) -> list:
    """Edges as getVisibleEdges/getHiddenEdges report them (page mm, y down) as polylines for line_overlay."""
    out = []
    for e in shown:
        points = e.discretize(Deflection=DEFLECTION)
        out.append([(p.x, p.y) for p in points])
    return out
