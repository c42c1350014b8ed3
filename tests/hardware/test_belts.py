# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The timing belts are solids of the assembly: each loop wraps both its pulleys at every angle of its joint
(the joint pulley turns about its own axis), so the interference sweep checks the belt's whole path."""
import math

import pytest
import yaml

from robogene_head.checks import interference
from robogene_head.geom import distance
from robogene_head_model.params import ParameterError, load
from robogene_head.parts import build_all, mounts


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
    pi times the MXL pitch differential, within the slack of rounding up to whole teeth."""
    pitch = params.geometry("pulleys").num("pitch_mxl")
    for key, joint, teeth in mounts.belts(params):
        belt = next(p for p in assembly.parts if p.name == f"{joint}_belt")
        stock = params.purchased(params.geometry("pulleys").text("belt"))
        width, back = stock.num("width"), stock.num("thickness") - stock.num("tooth_height")
        mean = belt.local.Volume() / width / back   # a band of constant thickness: area = mean perimeter x back
        expected = teeth * pitch - math.pi * mounts.pitch_differential(params) + math.pi * back
        assert expected - pitch < mean <= expected, (joint, mean, expected)   # less than a tooth of slack


def test_a_belt_wider_than_the_pulleys_is_named(params, external, tmp_path):
    data = yaml.safe_load(params.path.read_text())
    data["geometry"]["pulleys"]["width"] = 6
    path = tmp_path / "narrow.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ParameterError, match=r"purchased\.mxl-belt-6mm: a 6.4 mm wide belt does not run between "
                                             r"the flanges of 6 mm pulleys \(4.8 mm apart\)"):
        build_all(load(path), external)
