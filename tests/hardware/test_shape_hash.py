# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The build's cache keys hash a part's geometry, and only its geometry: exporting a part (which meshes it) must not
change its hash, or a package built from nothing redraws its drawings and pictures on the next build."""
import cadquery as cq
from OCP.BRepMesh import BRepMesh_IncrementalMesh

from robogene_head.export import shape_hash, write_stl


def _plate():
    return cq.Workplane().box(40, 20, 5).faces(">Z").workplane().hole(3.2).edges("|Z").fillet(2).val()


def test_exporting_a_part_leaves_its_hash_alone(tmp_path):
    plate = _plate()
    before = shape_hash(plate, "machined")
    write_stl(plate, tmp_path / "plate.stl")      # attaches a triangulation and marks sub-shapes checked
    assert (tmp_path / "plate.stl").stat().st_size > 0
    assert shape_hash(plate, "machined") == before


def test_a_meshed_and_an_unmeshed_build_of_the_same_geometry_hash_the_same():
    meshed, unmeshed = _plate(), _plate()
    BRepMesh_IncrementalMesh(meshed.wrapped, 0.01, False, 0.1, True).Perform()
    assert shape_hash(meshed) == shape_hash(unmeshed)


def test_geometry_and_labels_change_the_hash():
    plate = _plate()
    wider = cq.Workplane().box(40.01, 20, 5).faces(">Z").workplane().hole(3.2).edges("|Z").fillet(2).val()
    assert shape_hash(wider) != shape_hash(plate)
    assert shape_hash(plate, "machined") != shape_hash(plate, "printed")
