# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Parts as FCL triangle meshes, for the checks that measure mesh distances (interference, assembly sequence,
harness clearance).

A copy of the shape is meshed, never the shape itself: a triangulation left on a part's faces changes what its
BoundingBox() gives every later step of the build (and a moved or placed shape shares its faces with the part), so
those steps would depend on whether the meshing step ran or was skipped by the cache. The fab's cache keys of the
checks hash this file with their own."""
from __future__ import annotations

import cadquery as cq
import fcl
import numpy as np


def triangles(shape: cq.Shape, deflection: float, angular: float) -> tuple[np.ndarray, np.ndarray]:
    """(vertices N x 3 float, triangles M x 3 int32) of a copy of `shape`, meshed by CadQuery's tessellate at
    `deflection` and `angular` tolerance (rad). The shape keeps no triangulation."""
    verts, tris = shape.copy().tessellate(deflection, angular)
    v = np.array([(q.x, q.y, q.z) for q in verts], dtype=float).reshape(-1, 3)
    t = np.array(tris, dtype=np.int32).reshape(-1, 3)
    return v, t


def bvh(vertices: np.ndarray, tris: np.ndarray) -> fcl.BVHModel:
    model = fcl.BVHModel()
    model.beginModel(len(vertices), len(tris))
    model.addSubModel(vertices, tris)
    model.endModel()
    return model


def shape_bvh(shape: cq.Shape, deflection: float, angular: float) -> fcl.BVHModel:
    """The FCL model of a copy of `shape` (see triangles)."""
    return bvh(*triangles(shape, deflection, angular))
