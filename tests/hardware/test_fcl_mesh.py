# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The checks' FCL meshes: a part is meshed through a copy, so its BoundingBox() is the same whether or not a check
meshed it; the mesh is the one CadQuery's tessellate gives the shape; the model measures distances as FCL does."""
import cadquery as cq
import fcl
import numpy as np
import pytest

from robogene_head import fcl_mesh, geom


def _box(shape):
    b = shape.BoundingBox()
    return (b.xmin, b.ymin, b.zmin, b.xmax, b.ymax, b.zmax)


@pytest.mark.parametrize("make", [lambda: geom.sphere(7), lambda: geom.cyl("z", 10, 0, 10)], ids=["sphere", "cylinder"])
def test_meshing_leaves_the_shapes_bounding_box_alone(make):
    # Meshed in place, the box changes (CadQuery bounds the triangulation when there is one): what a copy avoids.
    meshed = make()
    before = _box(meshed)
    meshed.tessellate(0.1, 0.3)
    assert _box(meshed) != before
    shape = make()
    fcl_mesh.triangles(shape, 0.1, 0.3)
    assert _box(shape) == before
    # A placed shape shares its faces with the part: meshing it through a copy leaves the part alone too.
    fcl_mesh.meshed_copy(shape.moved(cq.Location(cq.Vector(5, 0, 0))), 0.1, 0.3)
    assert _box(shape) == before


def test_the_mesh_is_tessellates_own():
    ball = geom.sphere(7)
    v, t = fcl_mesh.triangles(ball, 0.05, 0.2)
    verts, tris = geom.sphere(7).tessellate(0.05, 0.2)
    assert v.dtype == float and v.shape == (len(verts), 3) and t.dtype == np.int32 and t.shape == (len(tris), 3)
    assert np.array_equal(v, [(q.x, q.y, q.z) for q in verts]) and np.array_equal(t, tris)


def test_the_model_measures_mesh_distances():
    model = fcl_mesh.bvh(*fcl_mesh.triangles(geom.sphere(7), 0.1, 0.3))
    a = fcl.CollisionObject(model, fcl.Transform())
    b = fcl.CollisionObject(model, fcl.Transform(np.array([20.0, 0, 0])))
    assert geom.mesh_distance(a, b) == pytest.approx(6.0, abs=0.2)     # 20 mm apart less two radii, to the mesh
