# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Which holes of the machined parts are tapped, and for which thread, found in the assembly: a hole that a
screw's shank or a standoff's stud fills exactly. The parts draw a tapped hole at the thread's nominal diameter
and a clearance hole larger (ISO 273), so a fastener whose shank has the diameter of the hole it sits in is
screwed into it. A STEP file cannot tell a tapped hole from a drilled one; the drawings get this list instead.

Each hole is given in its design's own frame (the STEP file's), once per design however many instances and
fasteners share it."""
from __future__ import annotations

import math
from dataclasses import dataclass

from OCP.BRepAdaptor import BRepAdaptor_Surface
from OCP.GeomAbs import GeomAbs_Cylinder
from OCP.gp import gp_Dir, gp_Pnt

from robogene_head_model.params import HeadParameters

TOL = 1e-3      # mm: a shank and a hole share their axis and diameter to this

# ISO 261 coarse pitches of the metric threads a head may use: the tap drill is the diameter less the pitch.
COARSE_PITCH = {1.6: 0.35, 2.0: 0.4, 2.5: 0.45, 3.0: 0.5, 4.0: 0.7, 5.0: 0.8, 6.0: 1.0, 8.0: 1.25}


@dataclass(frozen=True)
class TappedHole:
    thread: str          # "M3"
    diameter: float      # nominal: the hole as drawn
    pitch: float
    point: tuple         # the point of the hole's axis nearest the design's origin
    direction: tuple     # unit vector along the axis (first non-zero component positive)
    span: tuple          # where the hole's cylinder lies along the axis: (lo, hi) from point, along direction

    @property
    def tap_drill(self) -> float:
        return round(self.diameter - self.pitch, 3)

    def as_dict(self) -> dict:
        return {"thread": self.thread, "diameter": self.diameter, "pitch": self.pitch, "tap_drill": self.tap_drill,
                "point": list(self.point), "direction": list(self.direction), "span": list(self.span)}


def shanks(params: HeadParameters, part) -> list:
    """(diameter, z0, z1) of a purchased fastener's threaded shanks along its own z: a screw's or a set screw's shank
    (z 0..length), a male standoff's stud (z -stud_length..0). Empty for anything else."""
    catalog = params.root.node("purchased")
    if part.kind != "purchased" or not catalog.has(part.design):
        return []
    item = params.purchased(part.design)
    kind = item.text("kind") if item.has("kind") else ""
    if kind in ("screw", "set_screw"):
        return [(item.num("diameter"), 0.0, item.num("length"))]
    if kind == "standoff" and item.has("stud_length"):
        return [(item.num("thread"), -item.num("stud_length"), 0.0)]
    return []


def _line(point, direction) -> tuple:
    """A line as (nearest point to the origin, direction with its first non-zero component positive), rounded."""
    d = list(direction)
    first = next(c for c in d if abs(c) > 1e-9)
    d = [c / math.copysign(math.sqrt(sum(v * v for v in d)), first) for c in d]
    along = sum(p * c for p, c in zip(point, d))
    p = [pc - along * c for pc, c in zip(point, d)]
    return tuple(round(v, 4) + 0.0 for v in p), tuple(round(v, 6) + 0.0 for v in d)


def _dot(a, b) -> float:
    return sum(x * y for x, y in zip(a, b))


def _cylinders(shape) -> list:
    """(diameter, point on the axis, axis direction, v0, v1) of every cylindrical face: the face spans
    point + v * direction for v in v0..v1."""
    out = []
    for face in shape.Faces():
        surf = BRepAdaptor_Surface(face.wrapped)
        if surf.GetType() != GeomAbs_Cylinder:
            continue
        axis = surf.Cylinder().Axis()
        o, a = axis.Location(), axis.Direction()
        out.append((2 * surf.Cylinder().Radius(), (o.X(), o.Y(), o.Z()), (a.X(), a.Y(), a.Z()),
                    surf.FirstVParameter(), surf.LastVParameter()))
    return out


def _in_frame(location, point, direction) -> tuple:
    trsf = location.wrapped.Transformation()
    p = gp_Pnt(*point).Transformed(trsf)
    d = gp_Dir(*direction).Transformed(trsf)
    return (p.X(), p.Y(), p.Z()), (d.X(), d.Y(), d.Z())


def _span(point, direction, v0, v1, unit) -> tuple:
    """Where point + v * direction, v in v0..v1, lies along the unit vector."""
    base, sign = _dot(point, unit), _dot(direction, unit)
    return tuple(sorted((base + v0 * sign, base + v1 * sign)))


def tapped_holes(params: HeadParameters, parts: list) -> dict:
    """design -> [TappedHole] for every machined design with a fastener screwed into it."""
    fasteners = [(p, s) for p in parts for s in shanks(params, p)]
    found: dict = {}
    cylinders: dict = {}
    for part in parts:
        if part.kind != "machined":
            continue
        cyl = cylinders.setdefault(part.design, _cylinders(part.local))
        to_design = part.placement.inverse
        for fastener, (diameter, z0, z1) in fasteners:
            if fastener.link != part.link:
                continue
            point, direction = _in_frame(to_design * fastener.placement, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0))
            line = _line(point, direction)
            shank = _span(point, direction, z0, z1, line[1])
            for d, c_point, c_dir, v0, v1 in cyl:
                c_line = _line(c_point, c_dir)
                if abs(d - diameter) > TOL or math.dist(c_line[0], line[0]) > TOL:
                    continue
                if math.dist(c_line[1], line[1]) > TOL:
                    continue
                hole = _span(c_point, c_dir, v0, v1, line[1])
                if min(shank[1], hole[1]) - max(shank[0], hole[0]) > TOL:      # the shank reaches into it
                    nominal = round(diameter, 3)
                    span = (round(hole[0], 4) + 0.0, round(hole[1], 4) + 0.0)
                    found.setdefault(part.design, {})[(line, span)] = TappedHole(
                        f"M{nominal:g}", nominal, COARSE_PITCH.get(nominal, 0.0), *line, span)
    return {design: sorted(holes.values(), key=lambda h: (h.direction, h.point, h.span))
            for design, holes in found.items()}
