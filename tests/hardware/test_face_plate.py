# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The OpenSCAD face plate is a part of the head: in the assembly (from the STL OpenSCAD renders), bolted to the
side plates by four screws the BOM counts, clear of the eye drives at full tilt, in the made-parts BOM and
the mass. The loose printables (camera spacer jig, cable clips) are not on the head."""
import csv
import json

import numpy as np
import pytest
import trimesh

from robogene_head import mesh_solid, massprops, openscad
from robogene_head.assembly import Assembly
from robogene_head.checks import interference
from robogene_head.geom import distance

TETRA_V = [[0, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 10]]
TETRA_F = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]


def _part(assembly, name):
    return next(p for p in assembly.parts if p.name == name)


def test_face_plate_is_the_openscad_solid_on_the_side_plates(params, assembly, tmp_path):
    face = _part(assembly, "face_plate")
    assert (face.kind, face.material, face.link) == ("printed", "petg-printed", "head_frame")
    # The B-rep made from the STL encloses the STL's volume.
    fresh = tmp_path / "face_plate.stl"
    openscad.render_stl(openscad.SCAD_DIR / "face_plate.scad", openscad.defines(params)["face_plate"], fresh)
    stl = trimesh.load(str(fresh), force="mesh")
    assert face.local.Volume() == pytest.approx(stl.volume, rel=1e-9)
    head = params.geometry("head")
    x_front, hw = head.node("side_plate").num("x_max"), head.node("floor").num("half_width")
    bb = face.shape.BoundingBox()
    assert np.allclose([bb.xmin, bb.xmax, bb.ymin, bb.ymax, bb.zmin, bb.zmax],
                       [x_front, x_front + 3, -hw, hw, 0, head.node("side_plate").num("height")], atol=1e-6)


def test_face_plate_screws_go_through_its_holes_into_the_side_plates(params, assembly):
    screws = [p for p in assembly.parts if p.name.startswith("face_plate_screw_")]
    assert len(screws) == 4 and {p.design for p in screws} == {"iso7380-M3x8"}
    names = ["face_plate", "head_side_plate_left", "head_side_plate_right"] + [p.name for p in screws]
    report = interference.check(params, Assembly(params, [_part(assembly, n) for n in names]), [{}])
    assert report.interferences == []
    for screw in screws:
        side = _part(assembly, "head_side_plate_left" if "left" in screw.name else "head_side_plate_right")
        # seated in the tapped hole (touching its wall), through the plate's 3.4 mm hole (not touching it)
        assert distance(screw.shape, side.shape) < 1e-6
        assert screw.shape.intersect(side.shape).Volume() < interference.VOLUME_TOLERANCE
        # the head bears on the plate's front face; the shank passes its hole with 0.2 mm to spare
        shank = screw.shape.intersect(_part(assembly, "face_plate").shape)
        assert shank.Volume() < interference.VOLUME_TOLERANCE


def test_face_plate_clears_the_eye_drives_at_full_tilt(params, assembly):
    moving = [p for p in assembly.parts if p.link in ("eyes_tilt_link", "left_eye", "right_eye")]
    small = Assembly(params, [_part(assembly, "face_plate")] + moving)
    lo, hi = params.control_limits["eyes_tilt"]
    report = interference.check(params, small, [{"eyes_tilt": lo}, {"eyes_tilt": hi},
                                                {"eyes_tilt": hi, "eyes_version": 30}])
    assert report.ok, interference.format_report(report, report.minimum)
    closest = min(r.distance for r in report.clearances.values())
    assert closest >= params.geometry("clearances").num("minimum")


def test_face_plate_in_the_package(fab, params, assembly):
    made = {r["design"]: r for r in csv.DictReader((fab / "bom" / "robogene-head-made-parts.csv").open())}
    assert made["face_plate"]["process"] == "printed" and made["face_plate"]["qty_per_head"] == "1"
    assert made["face_plate"]["stl"] == "stl/face_plate.stl"
    bom = {r["key"]: r["qty_per_head"] for r in csv.DictReader((fab / "bom" / "robogene-head-bom.csv").open())}
    assert int(bom["iso7380-M3x8"]) == sum(1 for p in assembly.parts if p.design == "iso7380-M3x8") >= 4
    mass = json.loads((fab / "reports" / "mass.json").read_text())
    frame = [p for p in assembly.parts if p.link == "head_frame"]
    assert mass["links"]["head_frame"]["mass_kg"] == pytest.approx(
        sum(massprops.part_props(params, p).mass for p in frame), abs=1e-6)
    face = massprops.part_props(params, _part(assembly, "face_plate")).mass
    density = params.root.node("materials").num("petg-printed")
    assert face == pytest.approx(_part(assembly, "face_plate").local.Volume() * density * 1e-9)
    checked = {r["file"] for r in json.loads((fab / "reports" / "freecad-step-check.json").read_text())["files"]}
    assert "face_plate.step" in checked


def test_loose_printables_are_not_on_the_head(assembly, fab):
    designs = {p.design for p in assembly.parts}
    assert "camera_spacer" not in designs and "cable_clip" not in designs
    for name in ("camera_spacer", "cable_clip"):
        assert (fab / "stl" / f"{name}.stl").exists()


def test_a_closed_stl_becomes_a_solid(tmp_path):
    path = tmp_path / "t.stl"
    trimesh.Trimesh(vertices=np.array(TETRA_V, float), faces=np.array(TETRA_F), process=False).export(str(path))
    solid = mesh_solid.solid_from_stl(path)
    assert solid.isValid() and solid.Volume() == pytest.approx(1000 / 6)


def test_an_open_stl_is_named(tmp_path):
    path = tmp_path / "open.stl"
    trimesh.Trimesh(vertices=np.array(TETRA_V, float), faces=np.array(TETRA_F[:3]), process=False).export(str(path))
    with pytest.raises(mesh_solid.MeshSolidError, match=rf"{path}: the mesh is not closed"):
        mesh_solid.solid_from_stl(path)
    with pytest.raises(mesh_solid.MeshSolidError, match=r"STL not found"):
        mesh_solid.solid_from_stl(tmp_path / "none.stl")
