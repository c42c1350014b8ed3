# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Small solid builders on top of CadQuery, so part modules read like a drawing."""
from __future__ import annotations

import cadquery as cq
import fcl
import numpy as np
from OCP.Bnd import Bnd_Box
from OCP.BRepBndLib import BRepBndLib
from OCP.BRepExtrema import BRepExtrema_DistShapeShape
from OCP.gp import gp_Trsf

AXES = {"x": cq.Vector(1, 0, 0), "y": cq.Vector(0, 1, 0), "z": cq.Vector(0, 0, 1)}


def box(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> cq.Solid:
    """Axis-aligned box from its coordinate ranges."""
    if not (x0 < x1 and y0 < y1 and z0 < z1):
        raise ValueError(f"empty box {x0}..{x1} x {y0}..{y1} x {z0}..{z1}")
    return cq.Solid.makeBox(x1 - x0, y1 - y0, z1 - z0, cq.Vector(x0, y0, z0))


def cyl(axis: str, diameter: float, start: float, end: float, at: tuple[float, float] = (0.0, 0.0)) -> cq.Solid:
    """Cylinder along a principal axis from coordinate `start` to `end`; `at` = the other two coordinates
    in (y, z), (x, z) or (x, y) order."""
    lo, hi = min(start, end), max(start, end)
    a, b = at
    base = {"x": (lo, a, b), "y": (a, lo, b), "z": (a, b, lo)}[axis]
    return cq.Solid.makeCylinder(diameter / 2, hi - lo, cq.Vector(*base), AXES[axis])


def tube(axis: str, outside: float, bore: float, start: float, end: float, at=(0.0, 0.0)) -> cq.Shape:
    return cyl(axis, outside, start, end, at).cut(cyl(axis, bore, start - 1, end + 1, at))


def sphere(radius: float, centre=(0.0, 0.0, 0.0), poles: str = "z") -> cq.Solid:
    """Sphere whose poles lie on the given axis (cut the poles away: meshers leave slivers there)."""
    return cq.Solid.makeSphere(radius, cq.Vector(*centre), AXES[poles], angleDegrees1=-90, angleDegrees2=90)


def union(*shapes: cq.Shape) -> cq.Shape:
    result = shapes[0]
    for s in shapes[1:]:
        result = result.fuse(s)
    return result.clean()


def cut(shape: cq.Shape, *tools: cq.Shape) -> cq.Shape:
    for t in tools:
        shape = shape.cut(t)
    return shape.clean()


def single_solid(shape: cq.Shape, name: str) -> cq.Solid:
    """Parts are one solid each; a boolean that split a part is a design error worth stopping for."""
    solids = shape.Solids()
    if len(solids) != 1:
        raise ValueError(f"part {name}: expected one solid, got {len(solids)}")
    return solids[0]


def location(matrix: np.ndarray) -> cq.Location:
    """A 4x4 rigid transform (mm) as a CadQuery location."""
    trsf = gp_Trsf()
    m = matrix
    trsf.SetValues(m[0, 0], m[0, 1], m[0, 2], m[0, 3],
                   m[1, 0], m[1, 1], m[1, 2], m[1, 3],
                   m[2, 0], m[2, 1], m[2, 2], m[2, 3])
    return cq.Location(trsf)


def matrix(location: cq.Location) -> np.ndarray:
    """A CadQuery location as a 4x4 rigid transform (mm): the inverse of `location`."""
    t = location.wrapped.Transformation()
    m = np.eye(4)
    for i in range(3):
        for j in range(4):
            m[i, j] = t.Value(i + 1, j + 1)
    return m


def part_frame(poses: dict[str, np.ndarray], part) -> np.ndarray:
    """A part's design frame in the world (4x4, mm): its link's pose (`poses`, by link) after its placement."""
    return poses[part.link] @ matrix(part.placement)


def exact_bounds(shape: cq.Shape) -> tuple[np.ndarray, np.ndarray]:
    """(lower corner, upper corner) of the shape's bounding box from its geometry alone. CadQuery's BoundingBox()
    uses a triangulation when the shape has one, so a part meshed earlier in the run (a fresh build exports its STL)
    and the same part in a rebuild (STL cached) gave different boxes, and so different cache keys and lengths."""
    found = Bnd_Box()
    BRepBndLib.AddOptimal_s(shape.wrapped, found, False, False)
    x0, y0, z0, x1, y1, z1 = found.Get()
    return np.array([x0, y0, z0]), np.array([x1, y1, z1])


def distance(a: cq.Shape, b: cq.Shape) -> float:
    """The exact least distance between two shapes (0 where they touch or overlap)."""
    tool = BRepExtrema_DistShapeShape(a.wrapped, b.wrapped)
    tool.Perform()
    if not tool.IsDone():
        raise RuntimeError("BRepExtrema failed")
    return tool.Value()


def mesh_distance(a: fcl.CollisionObject, b: fcl.CollisionObject) -> float:
    """The least distance between two placed meshes (FCL; negative or 0 where they overlap): a quick bound before the
    exact one."""
    return fcl.distance(a, b, fcl.DistanceRequest(), fcl.DistanceResult())
