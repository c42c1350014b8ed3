# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The timing belts are solids of the assembly: each loop wraps both its pulleys at every angle of its joint
(the joint pulley turns about its own axis), so the interference sweep checks the belt's whole path."""
import math

import pytest
import yaml

from robogene_head.checks import interference
from robogene_head import geom
from robogene_head.geom import distance
from robogene_head_model.params import ParameterError, load
from robogene_head.parts import build_all, mounts

from param_variants import edited


@pytest.mark.parametrize("joint, angles", [("neck_yaw", (-45, 0, 45)), ("eyes_tilt", (-30, 0, 30))])
def test_each_belt_wraps_both_its_pulleys_at_every_angle(params, assembly, joint, angles):
    fit = params.geometry("clearances").num("fit_tolerance")
    names = (f"{joint}_belt", f"{joint}_motor_pulley", f"{joint}_joint_pulley")
    for angle in angles:
        placed = {p.part.name: p.shape for p in assembly.pose({joint: angle}) if p.part.name in names}
        belt = placed[names[0]]
        for pulley in names[1:]:
            assert distance(belt, placed[pulley]) < fit, (angle, pulley)
            assert belt.intersect(placed[pulley]).Volume() < interference.VOLUME_TOLERANCE, (angle, pulley)


def test_the_belt_loop_is_as_long_as_the_belt(params, assembly):
    """The back's inner edge runs on the pulleys' outside diameters: its length is the pitch-line length less
    pi times the pitch differential, within the slack of rounding up to whole teeth."""
    for key, joint, teeth in mounts.belts(params):
        pitch = mounts.belt_pitch(params, joint)
        belt = next(p for p in assembly.parts if p.name == f"{joint}_belt")
        stock = params.purchased(mounts.belt_key(params, joint))
        width, back = stock.num("width"), stock.num("thickness") - stock.num("tooth_height")
        mean = belt.local.Volume() / width / back   # a band of constant thickness: area = mean perimeter x back
        expected = teeth * pitch - math.pi * mounts.pitch_differential(params) + math.pi * back
        assert expected - pitch < mean <= expected, (joint, mean, expected)   # less than a tooth of slack


def test_a_belt_wider_than_the_pulleys_is_named(params, external, tmp_path):
    data = yaml.safe_load(params.path.read_text())
    data["geometry"]["pulleys"]["tilt"]["width"] = 6
    path = tmp_path / "narrow.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ParameterError, match=r"purchased\.xl-belt-037: a 10\.025 mm wide belt \(at its widest\) does "
                                             r"not run between the flanges of the eyes_tilt stage's 6 mm pulleys "
                                             r"\(1\.5 thick, 3 mm apart\)"):
        build_all(load(path), external)


def test_the_catalogue_pulleys_are_drawn_with_their_own_flanges(params):
    """The XL 037 pulleys' flanges are 1.5 mm thick (the maker's figure), not the 0.6 of pulleys.flange: the toothed
    body runs 11.3 mm between them, where the XL belt, at its widest 9.525 + 0.5, has 1.275 mm of room."""
    for joint in ("neck_yaw", "eyes_tilt"):
        assert mounts.flange_thickness(params, joint) == 1.5
        assert mounts.belt_room(params, joint) == (pytest.approx(1.275), pytest.approx(11.3), pytest.approx(10.025))
    shape = mounts.pulley(params, "eyes_tilt", 14, 6)
    toothed = 14 * 5.08 / math.pi - 0.508
    for z, across in ((0.75, 28.0), (1.45, 28.0), (1.55, toothed), (14.3 - 1.55, toothed), (14.3 - 0.75, 28.0)):
        slab = shape.intersect(geom.cyl("z", 40, z - 0.01, z + 0.01))
        assert slab.BoundingBox().xlen == pytest.approx(across, abs=0.01), z


def test_a_belt_at_its_widest_between_thick_flanges_is_refused(tmp_path, external):
    """2.2 mm flanges leave 9.9 mm: the belt's nominal 9.525 would pass, its widest (+0.5) does not."""
    params = edited(tmp_path, lambda d: d["geometry"]["pulleys"]["tilt"].update(flange_thickness=2.2))
    with pytest.raises(ParameterError, match=r"purchased\.xl-belt-037: a 10\.025 mm wide belt \(at its widest\) does "
                                             r"not run between the flanges of the eyes_tilt stage's 14\.3 mm pulleys "
                                             r"\(2\.2 thick, 9\.9 mm apart\)"):
        build_all(params, external)


def test_each_stage_draws_its_pulleys_and_belt_at_its_own_pitch(params, tmp_path):
    """The tilt pulleys come out at XL diameters (14T: pitch 22.64, outside 22.13, the catalogue's 28 mm flanges, its
    own rim) and 14.3 mm wide, its belt is cut from the XL stock to 2C + pi (D + d) / 2 + (D - d)^2 / 4C = 269.19 mm
    at the motor's 85.95 mm, so 53 teeth (106XL); the yaw stage's, on the same XL stock from 14T to 20T, 176.1 mm at
    its jackshaft's 44.6 mm, so 35 teeth (70XL), and a yaw stage back on MXL stock its old 2.032 mm pitch. Moved
    back to the old 86.05 mm the tilt belt needs 54 teeth."""
    box = mounts.pulley(params, "eyes_tilt", 14, 3).BoundingBox()
    assert (box.xlen, box.zlen) == (pytest.approx(28.0, abs=0.01), pytest.approx(14.3))
    yaw = mounts.pulley(params, "neck_yaw", 20, 15).BoundingBox()
    assert (yaw.xlen, yaw.zlen) == (pytest.approx(20 * 5.08 / math.pi - 0.508 + 2 * 2.93), pytest.approx(14.3))
    assert mounts.belts(params) == [("xl-belt-35T", "neck_yaw", 35), ("xl-belt-53T", "eyes_tilt", 53)]
    mxl = edited(tmp_path, lambda data: data["geometry"]["pulleys"]["yaw"].update(
        belt="mxl-belt-6mm", pitch=2.032, width=8, rim=1.5, flange_thickness=0.6))
    small = mounts.pulley(mxl, "neck_yaw", 14, 4).BoundingBox()
    assert (small.xlen, small.zlen) == (pytest.approx(14 * 2.032 / math.pi - 0.508 + 3), pytest.approx(8))
    old = edited(tmp_path, lambda data: data["geometry"]["head"]["tilt_motor"].update(x=-35, z=85))
    assert mounts.belts(old)[1] == ("xl-belt-54T", "eyes_tilt", 54)
    loop = mounts.belt_loop(params, "eyes_tilt", 85.95, 24, 14)
    assert loop.BoundingBox().zlen == pytest.approx(9.525)
    assert "XL pulley, 24 teeth, pitch dia. 38.81" in mounts.pulley_note(params, "eyes_tilt", 24, 6, set_screws=True)
