# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The drive sizing check: its worst-case search against closed-form results, the package's table against a
recomputation from the CAD, and an undersized drive that the check (and the build) refuses."""
import json
import math
import shutil

import numpy as np
import pytest
import yaml

from robogene_head import drive_sizing, fab as fab_mod, massprops

from robogene_head_model import drive_limits
from robogene_head.massprops import MassProps
from robogene_head_model.params import DEFAULT_PATH, ParameterError, load
from robogene_head.kinematics import rotation
from robogene_head.pose_search import GRAVITY, Chain
from robogene_head.progress import Progress

from param_variants import edited_file

# A sizing searches the whole range of every joint: seconds on an idle 2-core machine, minutes on a shared one.
HEAVY = pytest.mark.timeout(900)


def _point(mass, at):
    return MassProps(mass, np.array(at, dtype=float), np.zeros((3, 3)))


@HEAVY
def test_a_point_mass_above_the_neck_gives_the_closed_form_worst_case(params):
    """A 1 kg point h above the yaw joint: about pitch, gravity is largest at the pitch limit furthest from upright
    (roll at zero), m g d sin(30 deg), d the height above the pitch axis; its inertia about pitch is m d^2 at zero
    roll. About roll, m g d' sin(20 deg) with d' above the roll axis."""
    h = 60.0
    worst = Chain(params, {"head_frame": _point(1.0, [0, 0, h])}).worst()
    z_roll, z_yaw = params.joints["neck_roll"].origin[2], params.joints["neck_yaw"].origin[2]
    d, d_roll = (z_roll + z_yaw + h) / 1000, (z_yaw + h) / 1000
    pitch_limit = max(abs(params.joints["neck_pitch"].lower), abs(params.joints["neck_pitch"].upper))
    roll_limit = max(abs(params.joints["neck_roll"].lower), abs(params.joints["neck_roll"].upper))
    gravity, inertia = worst["neck_pitch"]
    assert gravity.value == pytest.approx(GRAVITY * d * math.sin(math.radians(pitch_limit)), rel=1e-6)
    assert abs(gravity.pose["neck_pitch"]) == pytest.approx(pitch_limit)
    assert inertia.value == pytest.approx(d * d, rel=1e-6)
    assert worst["neck_roll"][0].value == pytest.approx(GRAVITY * d_roll * math.sin(math.radians(roll_limit)), rel=1e-6)
    # on the yaw axis, the point makes no yaw torque in any pose and has no inertia about it
    assert worst["neck_yaw"][0].value == pytest.approx(0, abs=1e-12)
    assert worst["neck_yaw"][1].value == pytest.approx(0, abs=1e-12)


@HEAVY
def test_an_offset_mass_loads_yaw_only_when_the_neck_leans(params):
    """A point r in front of the yaw axis: no torque about yaw while the neck stands upright, some when it leans.
    Brute force on its own: the point's torque about the leaning yaw axis, a . (d x m g), over a fine grid of pitch,
    roll and yaw (yaw within its limits, so the point cannot always turn to where gravity pulls hardest); its
    inertia about yaw is m r^2 in every pose."""
    r = 0.05
    worst = Chain(params, {"head_frame": _point(1.0, [r * 1000, 0, 0])}).worst()
    pitch, roll, yaw = (params.joints[n] for n in ("neck_pitch", "neck_roll", "neck_yaw"))
    best = 0.0
    for p in np.linspace(pitch.lower, pitch.upper, 27):
        for q in np.linspace(roll.lower, roll.upper, 21):
            lean = rotation(pitch.axis, math.radians(p)) @ rotation(roll.axis, math.radians(q))
            axis = lean @ np.array(yaw.axis)
            ys = np.radians(np.linspace(yaw.lower, yaw.upper, 901))
            d = (lean @ np.array([r * np.cos(ys), r * np.sin(ys), np.zeros_like(ys)])).T   # yaw turns about +z
            best = max(best, float(np.max(np.abs(np.cross(d, [0, 0, -GRAVITY]) @ axis))))
    assert worst["neck_yaw"][0].value == pytest.approx(best, rel=1e-5)
    upright = Chain(params, {"head_frame": _point(1.0, [r * 1000, 0, 0])}).gravity_and_inertia(np.zeros((1, 6)))
    assert upright["neck_yaw"][0][0] == pytest.approx(0, abs=1e-12)
    assert worst["neck_yaw"][1].value == pytest.approx(r * r, rel=1e-9)


@pytest.fixture(scope="module")
def link_props(params, assembly):
    return massprops.link_props(params, assembly.parts)


@HEAVY
def test_the_package_table_is_the_check_of_the_cad(fab, params, link_props):
    report = json.loads((fab / "reports" / "drive-sizing.json").read_text())
    again = drive_sizing.report_json(drive_sizing.size(params, link_props))
    assert report["ok"] and again["ok"]
    assert [j["joint"] for j in report["joints"]] == [j["joint"] for j in again["joints"]]
    for got, want in zip(report["joints"], again["joints"]):
        for key in ("gravity_Nm", "inertia_kgm2", "load_Nm", "rotor_Nm", "margin"):
            assert got[key] == pytest.approx(want[key], rel=1e-6), (got["joint"], key)
        assert got["margin"] >= report["required_margin"] == 1.5
    text = (fab / "reports" / "drive-sizing.txt").read_text()
    assert all(j["joint"] in text for j in report["joints"]) and "TOO SMALL" not in text


@HEAVY
def test_capacities_are_the_urdf_efforts(params, link_props):
    """The same catalogue data set the URDF's effort limits: the smaller capacity is the effort."""
    limits = drive_limits.limits(params)
    for row in drive_sizing.size(params, link_props).joints:
        assert min(row.motor_capacity_Nm, row.gearhead_capacity_Nm) == pytest.approx(limits[row.joint].effort, rel=1e-9)


@HEAVY
def test_the_motor_capacity_is_what_the_current_limit_allows(params, link_props):
    """kt x the board's current limit x N x eta where that is below the motor's continuous rating (pitch and roll,
    whose limits share their board's 4 A), the continuous rating where the limit allows more (yaw's 550 mA);
    kt = U / omega0 from the catalogue."""
    rows = {j.joint: j for j in drive_sizing.size(params, link_props).joints}
    data = yaml.safe_load(DEFAULT_PATH.read_text())
    for joint, starved in (("neck_pitch", True), ("neck_roll", True), ("neck_yaw", False)):
        drive = data["drives"][joint]
        motor, gear = data["purchased"][drive["motor"]], data["purchased"][drive["gearhead"]]
        kt = motor["voltage"] / (motor["no_load_speed_rpm"] * math.pi / 30)
        amps = data["motor_control"]["joints"][joint]["current_limit"] / 1000
        assert (kt * amps < motor["continuous_torque_mNm"] / 1000) == starved
        at_motor = min(kt * amps, motor["continuous_torque_mNm"] / 1000)
        pulleys = data["geometry"]["pulleys"]["yaw"]   # the yaw's belt stage after its gearhead
        belt = pulleys["joint_teeth"] / pulleys["motor_teeth"] if joint == "neck_yaw" else 1
        assert rows[joint].motor_capacity_Nm == pytest.approx(at_motor * gear["ratio"] * gear["efficiency"] * belt,
                                                              rel=1e-9)
        assert rows[joint].current_limited == starved


@HEAVY
def test_the_payload_adds_to_the_load(params, link_props, tmp_path):
    heavier = load(edited_file(tmp_path, lambda d: d["drive_sizing"]["payloads"][0].update(mass=1.2)))
    base = {j.joint: j for j in drive_sizing.size(params, link_props).joints}
    more = {j.joint: j for j in drive_sizing.size(heavier, link_props).joints}
    assert more["neck_pitch"].load_Nm > base["neck_pitch"].load_Nm
    assert more["neck_pitch"].case == "loaded"


@HEAVY
@pytest.mark.parametrize("edit, joint, limited", [
    (lambda d: d["purchased"][d["drives"]["neck_pitch"]["motor"]].update(continuous_torque_mNm=2), "neck_pitch", "motor"),
    (lambda d: d["purchased"][d["drives"]["neck_roll"]["gearhead"]].update(continuous_torque_Nm=0.05), "neck_roll", "gearhead"),
    (lambda d: d["drive_sizing"]["accelerations"].update(left_eye_pan=5e6), "left_eye_pan", "motor"),
    # the pitch motor's continuous rating needs 3.2 A; the board's old 2000 mA gave it 2.0 of the 3.2 N m
    (lambda d: d["motor_control"]["joints"]["neck_pitch"].update(current_limit=2000), "neck_pitch", "current limit"),
])
def test_an_undersized_drive_is_refused_with_the_table(params, link_props, tmp_path, edit, joint, limited):
    report = drive_sizing.size(load(edited_file(tmp_path, edit)), link_props)
    assert not report.ok
    bad = {j.joint: j for j in report.failures()}
    assert joint in bad and bad[joint].limited_by == limited
    with pytest.raises(drive_sizing.SizingError) as err:
        drive_sizing.enforce(report)
    message = str(err.value)
    assert f"{joint} ({bad[joint].margin:.2f})" in message and "TOO SMALL" in message
    assert all(name in message for name in params.joints)


@pytest.mark.timeout(1800)
def test_the_build_stops_on_an_undersized_drive(fab, params, tmp_path):
    """The whole build, from a copy of the package's caches, with a pitch motor a fifth as strong."""
    out = tmp_path / "fab"
    shutil.copytree(fab, out, ignore=shutil.ignore_patterns("drawings", "renders", "assembly", "bom", "electronics"))
    path = edited_file(tmp_path, lambda d: d["purchased"][d["drives"]["neck_pitch"]["motor"]].update(
        continuous_torque_mNm=d["purchased"][d["drives"]["neck_pitch"]["motor"]]["continuous_torque_mNm"] / 5))
    board = json.loads((fab / "manifest.json").read_text())["board_step"]["path"]
    with pytest.raises(fab_mod.BuildError, match=r"drives below the required margin 1\.5: neck_pitch"):
        fab_mod.build(out, path, [], None, Progress(), board_step=board)
    table = (out / "reports" / "drive-sizing.txt").read_text()
    assert "neck_pitch" in table and "TOO SMALL" in table


@HEAVY
@pytest.mark.parametrize("edit, message", [
    (lambda d: d["drive_sizing"].update(margin=0.5), r"drive_sizing\.margin: must be >= 1\.0, got 0\.5"),
    (lambda d: d["drive_sizing"]["accelerations"].pop("eyes_tilt"), r"drive_sizing\.accelerations\.eyes_tilt: missing"),
    (lambda d: d["drive_sizing"]["payloads"][0].update(link="nowhere"),
     r"drive_sizing\.payloads\[0\]\.link: 'nowhere' is not a moving link"),
    (lambda d: d["purchased"]["faulhaber-1717T012SR"].pop("rotor_inertia_gcm2"),
     r"purchased\.faulhaber-1717T012SR\.rotor_inertia_gcm2: missing"),
])
def test_bad_sizing_data_is_named(link_props, tmp_path, edit, message):
    path = edited_file(tmp_path, edit)
    with pytest.raises(ParameterError, match=f"^{path}: {message}$"):
        drive_sizing.size(load(path), link_props)
