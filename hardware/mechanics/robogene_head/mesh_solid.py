# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""A closed triangle mesh (an OpenSCAD printable's STL) as a B-rep solid, so the printable can join the
assembly, its checks and its mass properties like any CadQuery part.

The triangles are sewn into one shell and coplanar neighbours merged, so flat faces come out as single
faces; curved surfaces stay facetted exactly as OpenSCAD meshed them."""
from __future__ import annotations

from pathlib import Path

import cadquery as cq
from OCP.BRepBuilderAPI import BRepBuilderAPI_Sewing
from OCP.ShapeUpgrade import ShapeUpgrade_UnifySameDomain
from OCP.StlAPI import StlAPI_Reader
from OCP.TopoDS import TopoDS_Shape

SEWING_TOLERANCE = 1e-6   # mm: OpenSCAD writes shared vertices with identical coordinates


class MeshSolidError(ValueError):
    """The STL cannot be one closed solid; the message starts with the file."""


def solid_from_stl(path: Path | str) -> cq.Solid:
    path = Path(path)
    if not path.is_file():
        raise MeshSolidError(f"{path}: STL not found")
    triangles = TopoDS_Shape()
    if not StlAPI_Reader().Read(triangles, str(path)) or triangles.IsNull():
        raise MeshSolidError(f"{path}: not a readable STL file")
    sewing = BRepBuilderAPI_Sewing(SEWING_TOLERANCE)
    sewing.Add(triangles)
    sewing.Perform()
    sewn = cq.Shape.cast(sewing.SewedShape())
    shells = [sewn] if isinstance(sewn, cq.Shell) else sewn.Shells()
    if len(shells) != 1:
        raise MeshSolidError(f"{path}: the triangles form {len(shells)} shells, expected one closed shell")
    if not shells[0].Closed():
        raise MeshSolidError(f"{path}: the mesh is not closed ({sewing.NbFreeEdges()} free edges)")
    solid = cq.Solid.makeSolid(shells[0])
    if solid.Volume() < 0:   # triangles wound inwards
        solid = cq.Solid(solid.wrapped.Reversed())
    unify = ShapeUpgrade_UnifySameDomain(solid.wrapped, True, True, True)
    unify.Build()
    merged = cq.Shape.cast(unify.Shape())
    solids = merged.Solids()
    if len(solids) != 1 or not solids[0].isValid() or solids[0].Volume() <= 0:
        raise MeshSolidError(f"{path}: the mesh does not make one valid solid")
    return solids[0]
