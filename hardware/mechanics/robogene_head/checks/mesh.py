# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Mesh quality of every exported STL: watertight, manifold, consistently wound, no degenerate faces.

Counted directly on the triangle soup so the verdict does not depend on a mesh library's repair heuristics.
Vertices are merged on a 1e-4 mm grid: an STL repeats each vertex per triangle, and the same point can be
written as +1e-17 and -1e-17 by the mesher; anything further apart than the grid stays a separate vertex."""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import trimesh


@dataclass
class MeshCheck:
    path: str
    faces: int
    boundary_edges: int       # edges used by one face: holes
    nonmanifold_edges: int    # edges used by more than two faces
    misoriented_edges: int    # edges walked the same way by both faces: inconsistent winding
    degenerate_faces: int     # zero-area triangles
    volume: float             # mm^3, signed by winding (positive = outward normals)
    trimesh_volume: bool

    @property
    def defects(self) -> int:
        return self.boundary_edges + self.nonmanifold_edges + self.misoriented_edges + self.degenerate_faces

    @property
    def ok(self) -> bool:
        return self.faces > 0 and self.defects == 0 and self.volume > 0 and self.trimesh_volume


def check_stl(path: Path) -> MeshCheck:
    mesh = trimesh.load(str(path), force="mesh", process=False)
    if mesh.faces.size == 0:
        return MeshCheck(str(path), 0, 0, 0, 0, 0, 0.0, False)
    grid = np.round(np.asarray(mesh.vertices, dtype=float), 4) + 0.0   # + 0.0 turns -0.0 into 0.0
    verts, inverse = np.unique(grid, axis=0, return_inverse=True)
    faces = inverse.reshape(-1)[mesh.faces]
    directed = Counter()
    for a, b, c in faces:
        directed[(a, b)] += 1
        directed[(b, c)] += 1
        directed[(c, a)] += 1
    undirected = Counter()
    for (a, b), n in directed.items():
        undirected[(min(a, b), max(a, b))] += n
    boundary = sum(1 for n in undirected.values() if n == 1)
    nonmanifold = sum(1 for n in undirected.values() if n > 2)
    misoriented = sum(1 for (a, b), n in directed.items() if n > 1 and undirected[(min(a, b), max(a, b))] == 2)
    tri = verts[faces]
    areas = np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1) / 2
    degenerate = int(np.sum(areas <= 1e-12))
    volume = float(np.einsum("ij,ij->i", tri[:, 0], np.cross(tri[:, 1], tri[:, 2])).sum() / 6.0)
    tm = trimesh.Trimesh(vertices=verts, faces=faces, process=False)
    return MeshCheck(str(path), len(faces), boundary, nonmanifold, misoriented, degenerate, volume, bool(tm.is_volume))
