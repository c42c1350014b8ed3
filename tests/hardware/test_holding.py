# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""What holds the head when the power goes: each drive's holding brake against the worst gravity torque, and the
check (and the build) refusing a head whose brake is missing, too weak, or strong enough to overload its gearhead."""
import json
import shutil

import numpy as np
import pytest
import yaml

from robogene_head import drive_sizing, fab as fab_mod, holding, unpowered
from robogene_head.massprops import MassProps
from robogene_head.progress import Progress
from robogene_head_model import drive_limits
from robogene_head_model.params import DEFAULT_PATH, ParameterError, load

from param_variants import edited_file


def _point(mass, at):
    return MassProps(mass, np.array(at, dtype=float), np.zeros((3, 3)))


# A 1 kg point 1 mm in front of the head frame's axis and 60 mm up: pitch and roll both fall onto a stop. The worst
# gravity torques are given (the drive sizing finds them from the CAD): 1.124 N m about pitch, 0.654 about roll, as the
# package's sizing has them, so the brakes must hold 1.686 and 0.981 N m.
PROPS = {"head_frame": _point(1.0, [1, 2, 60])}
WORST = {"neck_pitch": 1.124, "neck_roll": 0.654, "neck_yaw": 0.1, "eyes_tilt": 0.05, "left_eye_pan": 0.0,
         "right_eye_pan": 0.0}


def _rows(params):
    return {r.joint: r for r in unpowered.analyse(params, PROPS, WORST)}


def test_holding_at_the_joint_is_the_static_torque_times_the_reduction(params):
    """No credit for the gear train's friction: static torque x N; it slips at that over eta."""
    data = yaml.safe_load(DEFAULT_PATH.read_text())
    for joint, ratio in (("neck_pitch", 66), ("neck_roll", 246)):
        brake = data["purchased"][data["drives"][joint]["brake"]]
        eta = data["purchased"][data["drives"][joint]["gearhead"]]["efficiency"]
        h = holding.holding(params, joint)
        assert h.at_joint_Nm == pytest.approx(brake["static_torque_mNm"] / 1000 * ratio, rel=1e-12)
        assert h.slip_Nm == pytest.approx(h.at_joint_Nm / eta, rel=1e-12)
        assert h.gearhead_rating_Nm == 4.5 and h.protects_gearhead
    assert not holding.holding(params, "neck_yaw").present


def test_the_design_holds_pitch_and_roll_with_margin(params):
    rows = _rows(params)
    for joint in ("neck_pitch", "neck_roll"):
        r = rows[joint]
        assert r.behaviour == "falls" and r.held and r.ok
        assert r.margin == pytest.approx(r.holding_Nm / WORST[joint]) and r.margin >= 1.5
        assert r.element == params.drive(joint).text("brake")
    unpowered.enforce(list(rows.values()))          # passes: nothing to raise


@pytest.mark.parametrize("edit, joint, message", [
    # the brake taken off: the head falls as it did before the brakes
    (lambda d: d["drives"]["neck_pitch"].pop("brake"), "neck_pitch", r"neck_pitch \(holds 0\.000 of 1\.686 N m\)"),
    # a quarter of the static torque: 10 mN m x 66 holds 0.66 of the 1.686 N m needed
    (lambda d: d["purchased"][d["drives"]["neck_pitch"]["brake"]].update(static_torque_mNm=10), "neck_pitch",
     r"neck_pitch \(holds 0\.660 of 1\.686 N m\)"),
    (lambda d: d["purchased"][d["drives"]["neck_roll"]["brake"]].update(static_torque_mNm=3), "neck_roll",
     r"neck_roll \(holds 0\.738 of 0\.981 N m\)"),
    # strong enough to hold, and to overload the 26/1 before it slips: 20 mN m x 246 / 0.55 = 8.95 N m > 4.5
    (lambda d: d["purchased"][d["drives"]["neck_roll"]["brake"]].update(static_torque_mNm=20), "neck_roll",
     r"neck_roll \(slips at 8\.945 N m, gearhead 4\.500\)"),
])
def test_a_missing_weak_or_overstrong_brake_is_refused_with_the_table(tmp_path, edit, joint, message):
    rows = unpowered.analyse(load(edited_file(tmp_path, edit)), PROPS, WORST)
    assert not {r.joint: r for r in rows}[joint].ok
    with pytest.raises(unpowered.UnpoweredError, match=f"^unpowered: {message}\n") as err:
        unpowered.enforce(rows)
    assert "FALLS" in str(err.value) or "OVERLOADS GEARHEAD" in str(err.value)
    assert all(name in str(err.value) for name in WORST)


@pytest.mark.parametrize("edit, message", [
    (lambda d: d["drives"]["neck_pitch"].update(brake="faulhaber-IE2-512"),
     r"drives\.neck_pitch\.brake: 'faulhaber-IE2-512' is a encoder, expected a brake"),
    (lambda d: d["drives"]["neck_roll"].update(brake="nowhere"), r"drives\.neck_roll\.brake: 'nowhere' is not listed"),
    (lambda d: d["purchased"][d["drives"]["neck_roll"]["brake"]].pop("static_torque_mNm"),
     r"purchased\.spec-brake-23-12V-8mNm\.static_torque_mNm: missing"),
])
def test_bad_brake_data_is_named(tmp_path, edit, message):
    path = edited_file(tmp_path, edit)
    with pytest.raises(ParameterError, match=f"^{path}: {message}"):
        load(path)


def test_the_brake_turns_with_the_rotor_in_the_sizing(params):
    """The drive sizing's rotor term: (motor rotor + brake hub and disc) x N^2 x eta x alpha."""
    data = yaml.safe_load(DEFAULT_PATH.read_text())
    # a mass beyond every joint (the sizing divides by each joint's load)
    props = dict(PROPS, left_eye=_point(0.05, [10, 0, 0]), right_eye=_point(0.05, [10, 0, 0]))
    rows = {j.joint: j for j in drive_sizing.size(params, props).joints}
    for joint in ("neck_pitch", "neck_roll"):
        drive = data["drives"][joint]
        inertia = (data["purchased"][drive["motor"]]["rotor_inertia_gcm2"]
                   + data["purchased"][drive["brake"]]["rotor_inertia_gcm2"]) * 1e-7
        n = drive_limits.reduction(params, joint)
        eta = data["purchased"][drive["gearhead"]]["efficiency"]
        alpha = np.radians(data["drive_sizing"]["accelerations"][joint])
        assert rows[joint].rotor_Nm == pytest.approx(inertia * n * n * eta * alpha, rel=1e-9)


def test_the_package_has_the_brakes_and_reports_the_head_held(fab, params):
    rows = {r["joint"]: r for r in json.loads((fab / "reports" / "unpowered.json").read_text())["joints"]}
    sizing = {j["joint"]: j for j in json.loads((fab / "reports" / "drive-sizing.json").read_text())["joints"]}
    for joint in ("neck_pitch", "neck_roll"):
        r = rows[joint]
        assert r["behaviour"] == "falls" and r["held"] and r["ok"]
        assert r["hold_Nm"] == pytest.approx(1.5 * sizing[joint]["gravity_Nm"])
        assert r["holding_Nm"] == pytest.approx(holding.holding(params, joint).at_joint_Nm)
        assert r["margin"] >= 1.5
    text = (fab / "reports" / "unpowered.txt").read_text()
    assert "FALLS" not in text and "OVERLOADS" not in text
    bom = (fab / "bom" / "robogene-head-bom.csv").read_text()
    assert "RG-BRAKE-32-12V-40mNm" in bom and "RG-BRAKE-23-12V-8mNm" in bom


@pytest.mark.timeout(1800)
def test_the_build_stops_on_a_head_that_would_fall(fab, tmp_path):
    """The whole build, from a copy of the package's caches, with a pitch brake a quarter as strong."""
    out = tmp_path / "fab"
    shutil.copytree(fab, out, ignore=shutil.ignore_patterns("drawings", "renders", "assembly", "bom", "electronics"))
    path = edited_file(tmp_path, lambda d: d["purchased"][d["drives"]["neck_pitch"]["brake"]].update(static_torque_mNm=10))
    board = json.loads((fab / "manifest.json").read_text())["board_step"]["path"]
    with pytest.raises(fab_mod.BuildError, match=r"^unpowered: neck_pitch \(holds 0\.660 of "):
        fab_mod.build(out, path, [], None, Progress(), board_step=board)
    assert "FALLS" in (out / "reports" / "unpowered.txt").read_text()
