# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The URDF's effort and velocity limits come from the drives' catalogue data in the parameter file: the test
recomputes them from the YAML on its own, follows a changed motor through to the URDF, and refuses bad data by
the key that holds it."""
import math
import xml.etree.ElementTree as ET

import pytest
import yaml

from robogene_head import urdf

from robogene_head_model import drive_limits
from robogene_head_model.params import DEFAULT_PATH, ParameterError, load

from param_variants import edited, edited_file

BELTS = {"neck_yaw": "yaw", "eyes_tilt": "tilt"}


def expected_limits(data: dict) -> dict[str, tuple[float, float]]:
    """(effort N m, velocity rad/s) per joint, straight from the YAML."""
    out = {}
    for joint, drive in data["drives"].items():
        motor, gear = data["purchased"][drive["motor"]], data["purchased"][drive["gearhead"]]
        teeth = data["geometry"]["pulleys"].get(BELTS.get(joint), {"joint_teeth": 1, "motor_teeth": 1})
        belt = teeth["joint_teeth"] / teeth["motor_teeth"]
        # kt = U / omega0; the board holds the motor to its current limit (the eye pans: the smaller of the eye
        # board's two axes)
        kt = motor["voltage"] / (motor["no_load_speed_rpm"] * 2 * math.pi / 60)
        control = data["motor_control"]["joints"]
        amps = (min(control["eyes_version"]["current_limit"], control["eyes_vergence"]["current_limit"])
                if joint.endswith("eye_pan") else control[joint]["current_limit"]) / 1000
        at_motor = min(motor["continuous_torque_mNm"] * 1e-3, kt * amps)
        at_gear_shaft = min(at_motor * gear["ratio"] * gear["efficiency"], gear["continuous_torque_Nm"])
        out[joint] = (at_gear_shaft * belt, motor["no_load_speed_rpm"] / 60 * 2 * math.pi / (gear["ratio"] * belt))
    return out


def urdf_limits(text: str) -> dict[str, tuple[float, float]]:
    root = ET.fromstring(text)
    return {j.get("name"): (float(j.find("limit").get("effort")), float(j.find("limit").get("velocity")))
            for j in root.findall("joint")}


def test_package_urdf_limits_follow_the_drives(fab):
    expected = expected_limits(yaml.safe_load(DEFAULT_PATH.read_text()))
    got = urdf_limits((fab / "urdf" / "robogene_head.urdf").read_text())
    assert set(got) == set(expected)
    for joint, (effort, velocity) in expected.items():
        assert got[joint][0] == pytest.approx(effort, rel=1e-8), joint
        assert got[joint][1] == pytest.approx(velocity, rel=1e-8), joint


def test_a_weaker_motor_lowers_its_joints_effort(params, tmp_path):
    before = urdf_limits(urdf.generate(params, {}))
    motor = params.drive("neck_pitch").text("motor")

    def halve(data):
        data["purchased"][motor]["continuous_torque_mNm"] /= 2
    after = urdf_limits(urdf.generate(edited(tmp_path, halve), {}))
    # half of 70 mN m is below what the board's current limit allows: the motor's rating sets the effort now
    data = yaml.safe_load(DEFAULT_PATH.read_text())
    assert after["neck_pitch"][0] == pytest.approx(data["purchased"][motor]["continuous_torque_mNm"] / 2e3 * 66 * 0.70,
                                                   rel=1e-8)
    assert after["neck_pitch"][0] < before["neck_pitch"][0]
    assert after["neck_pitch"][1] == before["neck_pitch"][1]
    assert {j: v for j, v in after.items() if j != "neck_pitch"} == \
           {j: v for j, v in before.items() if j != "neck_pitch"}


def test_the_board_current_limit_caps_the_effort(params, tmp_path):
    """Pitch: the board's limit, not the motor's continuous rating, sets its effort (kt x I x N x eta); halving the
    limit halves the effort. The eye pans take the smaller of the eye board's two axis limits, as its firmware does."""
    pitch = drive_limits.limit(params, "neck_pitch")
    kt = drive_limits.torque_constant(params, pitch.motor)
    assert pitch.limited_by == "current limit" and pitch.effort < pitch.rated
    assert pitch.effort == pytest.approx(kt * pitch.current_limit_mA / 1000 * 66 * 0.70, rel=1e-9)

    def edit(data):
        data["motor_control"]["joints"]["neck_pitch"]["current_limit"] = pitch.current_limit_mA / 2
        data["motor_control"]["joints"]["eyes_vergence"]["current_limit"] = 150
    limits = drive_limits.limits(edited(tmp_path, edit))
    assert limits["neck_pitch"].effort == pytest.approx(pitch.effort / 2, rel=1e-9)
    assert limits["left_eye_pan"].current_limit_mA == limits["right_eye_pan"].current_limit_mA == 150
    assert limits["left_eye_pan"].limited_by == "current limit"


def test_the_gearhead_rating_caps_the_torque_before_the_belt(tmp_path):
    """The 16/7 43:1 drives the eye pans directly and the eye tilt through the 24/14 belt: its rating caps the
    torque on its own shaft, which the belt then multiplies."""
    def derate(data):
        data["purchased"]["faulhaber-16-7-43"]["continuous_torque_Nm"] = 0.02
    limits = drive_limits.limits(edited(tmp_path, derate))
    assert (limits["left_eye_pan"].effort, limits["left_eye_pan"].limited_by) == (pytest.approx(0.02), "gearhead")
    assert (limits["eyes_tilt"].effort, limits["eyes_tilt"].limited_by) == (pytest.approx(0.02 * 24 / 14), "gearhead")


def test_belt_pull_is_the_gearhead_torque_on_the_motor_pulley(params):
    data = yaml.safe_load(DEFAULT_PATH.read_text())
    limits = drive_limits.limits(params)
    for joint, key in BELTS.items():
        teeth = data["geometry"]["pulleys"][key]
        radius = teeth["motor_teeth"] * teeth["pitch"] / (2 * math.pi) / 1000
        shaft_torque = expected_limits(data)[joint][0] * teeth["motor_teeth"] / teeth["joint_teeth"]
        assert limits[joint].belt_pull == pytest.approx(shaft_torque / radius, rel=1e-9), joint
    assert {j for j, lim in limits.items() if lim.belt_pull} == set(BELTS)


@pytest.mark.parametrize("part, field, value, message", [
    ("faulhaber-1717T012SR", "no_load_speed_rpm", None, "no_load_speed_rpm: missing"),
    ("faulhaber-2224U012SR", "continuous_torque_mNm", None, "continuous_torque_mNm: missing"),
    ("faulhaber-2224U012SR", "continuous_torque_mNm", -3, "continuous_torque_mNm: must be > 0, got -3"),
    ("faulhaber-16-7-43", "efficiency", 1.2, "efficiency: must be <= 1, got 1.2"),
    ("faulhaber-16-7-43", "efficiency", 0, "efficiency: must be > 0, got 0"),
    ("faulhaber-32-3-66", "continuous_torque_Nm", None, "continuous_torque_Nm: missing"),
])
def test_bad_drive_data_is_named(tmp_path, part, field, value, message):
    def edit(data):
        if value is None:
            del data["purchased"][part][field]
        else:
            data["purchased"][part][field] = value
    path = edited_file(tmp_path, edit)
    with pytest.raises(ParameterError, match=f"^{path}: purchased\\.{part}\\.{message}$"):
        urdf.generate(load(path), {})
