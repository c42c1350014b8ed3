# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Parts as FCL triangle meshes, for the checks that measure mesh distances (interference, assembly sequence,
harness clearance).

A copy of the shape is meshed, never the shape itself: a triangulation left on a part's faces changes what its
BoundingBox() gives every later step of the build (and a moved or placed shape shares its faces with the part), so
those steps would depend on whether the meshing step ran or was skipped by the cache. The copy itself keeps its mesh,
for the exact measures (meshed_copy). The fab's cache keys of the checks hash this file with their own."""
from __future__ import annotations

import cadquery as cq
import fcl
import numpy as np


def meshed_copy(shape: cq.Shape, deflection: float, angular: float) -> tuple[cq.Shape, np.ndarray, np.ndarray]:
    """(a copy of `shape` that keeps its triangulation, its vertices N x 3 float, its triangles M x 3 int32), meshed
    by CadQuery's tessellate at `deflection` and `angular` tolerance (rad). Exact measures belong on the copy:
    OpenCASCADE's distance bounds each face by its triangles where it has them and by its surface's control points
    where not, and on the head's curved parts the second is many times slower (minutes where a part the build has
    just exported, and so meshed, takes seconds)."""
    copy = shape.copy()
    verts, tris = copy.tessellate(deflection, angular)
    v = np.array([(q.x, q.y, q.z) for q in verts], dtype=float).reshape(-1, 3)
    t = np.array(tris, dtype=np.int32).reshape(-1, 3)
    return copy, v, t


def triangles(shape: cq.Shape, deflection: float, angular: float) -> tuple[np.ndarray, np.ndarray]:
    """(vertices, triangles) of a meshed copy of `shape` (see meshed_copy). The shape keeps no triangulation."""
    return meshed_copy(shape, deflection, angular)[1:]


def bvh(vertices: np.ndarray, tris: np.ndarray) -> fcl.BVHModel:
    model = fcl.BVHModel()
    model.beginModel(len(vertices), len(tris))
    model.addSubModel(vertices, tris)
    model.endModel()
    return model
