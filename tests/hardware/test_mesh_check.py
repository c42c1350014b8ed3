# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The mesh checker finds each kind of defect, and every STL of the package has none."""
import numpy as np
import pytest
import trimesh

from robogene_head.checks.mesh import check_stl


def _write(tmp_path, name, vertices, faces):
    path = tmp_path / name
    trimesh.Trimesh(vertices=np.array(vertices, float), faces=np.array(faces), process=False).export(str(path))
    return path


TETRA_V = [[0, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 10]]
TETRA_F = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]


def test_closed_tetrahedron_is_clean(tmp_path):
    result = check_stl(_write(tmp_path, "t.stl", TETRA_V, TETRA_F))
    assert result.ok and result.defects == 0
    assert result.volume == pytest.approx(1000 / 6)


def test_missing_face_is_a_hole(tmp_path):
    result = check_stl(_write(tmp_path, "t.stl", TETRA_V, TETRA_F[:3]))
    assert result.boundary_edges == 3 and not result.ok


def test_flipped_face_is_misoriented(tmp_path):
    faces = [f[:] for f in TETRA_F]
    faces[3] = faces[3][::-1]
    result = check_stl(_write(tmp_path, "t.stl", TETRA_V, faces))
    assert result.misoriented_edges > 0 and not result.ok


def test_fin_is_non_manifold(tmp_path):
    vertices = TETRA_V + [[5, 5, -8]]
    faces = TETRA_F + [[0, 1, 4], [0, 4, 1]]
    result = check_stl(_write(tmp_path, "t.stl", vertices, faces))
    assert result.nonmanifold_edges > 0 and not result.ok


def test_every_package_mesh_is_watertight_and_manifold(fab):
    stls = sorted(fab.glob("stl/*.stl")) + sorted(fab.glob("urdf/meshes/*.stl"))
    assert len(stls) >= 10
    bad = [(p.name, r.boundary_edges, r.nonmanifold_edges, r.misoriented_edges, r.degenerate_faces)
           for p in stls for r in [check_stl(p)] if not r.ok]
    assert bad == []
