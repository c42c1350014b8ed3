# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The round holes of a STEP file, measured with OpenCASCADE for the tests (the drawings measure them in FreeCAD):
each a run of coaxial whole-circle cylindrical faces with the material outside, along X, Y or Z; through when
there is no material just past either end, else blind, its depth from the open end to the bottom; a wider face
at an open end is a counterbore."""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import cadquery as cq
from OCP.BRepAdaptor import BRepAdaptor_Surface
from OCP.BRepClass3d import BRepClass3d_SolidClassifier
from OCP.BRepLProp import BRepLProp_SLProps
from OCP.GeomAbs import GeomAbs_Cylinder
from OCP.gp import gp_Pnt
from OCP.TopAbs import TopAbs_IN, TopAbs_REVERSED


@dataclass
class StepHole:
    axis: int                     # 0, 1, 2
    centre: tuple                 # the axis line's other two coordinates
    faces: list                   # (diameter, lo, hi) along the axis, by lo
    through: bool
    depth: float | None           # blind: open end to bottom
    counterbores: list = field(default_factory=list)   # (diameter, depth)

    @property
    def diameter(self) -> float:
        return min(d for d, _, _ in self.faces)


def _hole_faces(solid) -> list:
    out = []
    for face in solid.Faces():
        surf = BRepAdaptor_Surface(face.wrapped)
        if surf.GetType() != GeomAbs_Cylinder:
            continue
        if surf.LastUParameter() - surf.FirstUParameter() < 2 * math.pi - 1e-6:
            continue
        cyl = surf.Cylinder()
        a, o = cyl.Axis().Direction(), cyl.Location()
        axis = max(range(3), key=lambda i: abs((a.X(), a.Y(), a.Z())[i]))
        if abs(abs((a.X(), a.Y(), a.Z())[axis]) - 1) > 1e-9:
            continue
        u = (surf.FirstUParameter() + surf.LastUParameter()) / 2
        v = (surf.FirstVParameter() + surf.LastVParameter()) / 2
        props = BRepLProp_SLProps(surf, u, v, 1, 1e-6)
        n = props.Normal()
        if face.wrapped.Orientation() == TopAbs_REVERSED:
            n.Reverse()
        p = props.Value()
        d = (p.X() - o.X(), p.Y() - o.Y(), p.Z() - o.Z())
        along = d[0] * a.X() + d[1] * a.Y() + d[2] * a.Z()
        radial = (d[0] - along * a.X(), d[1] - along * a.Y(), d[2] - along * a.Z())
        if radial[0] * n.X() + radial[1] * n.Y() + radial[2] * n.Z() > 0:
            continue                    # a shaft
        origin = (o.X(), o.Y(), o.Z())
        sign = (a.X(), a.Y(), a.Z())[axis]
        ends = sorted(origin[axis] + sign * t for t in (surf.FirstVParameter(), surf.LastVParameter()))
        out.append((axis, tuple(round(origin[i], 4) for i in range(3) if i != axis), 2 * cyl.Radius(), *ends))
    return out


def holes(step) -> list:
    solid = cq.importers.importStep(str(step)).val()
    classifier = BRepClass3d_SolidClassifier(solid.wrapped)

    def material(axis, centre, t):
        p = list(centre)
        p.insert(axis, t)
        classifier.Perform(gp_Pnt(*p), 1e-6)
        return classifier.State() == TopAbs_IN

    lines = {}
    for axis, centre, d, lo, hi in _hole_faces(solid):
        lines.setdefault((axis, centre), set()).add((round(d, 4), round(lo, 4), round(hi, 4)))
    out = []
    for (axis, centre), faces in lines.items():
        faces = sorted(faces, key=lambda f: f[1])
        runs = [[faces[0]]]
        for f in faces[1:]:
            (runs[-1].append(f) if abs(f[1] - runs[-1][-1][2]) < 1e-4 else runs.append([f]))
        for run in runs:
            open_lo = not material(axis, centre, run[0][1] - 0.01)
            open_hi = not material(axis, centre, run[-1][2] + 0.01)
            if not (open_lo or open_hi):
                continue
            main = min(d for d, _, _ in run)
            hole = StepHole(axis, centre, run, open_lo and open_hi,
                            None if open_lo and open_hi else run[-1][2] - run[0][1])
            for end, (d, lo, hi) in ((open_lo, run[0]), (open_hi and len(run) > 1, run[-1])):
                if end and d > main + 1e-4:
                    hole.counterbores.append((d, hi - lo))
            out.append(hole)
    return out
