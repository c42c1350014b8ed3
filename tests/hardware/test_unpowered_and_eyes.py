# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""What the joints do unpowered (inverted pendulums fall, pendulums settle), against closed-form results; the eye-pan
hard stops against the geometry (the lug meets its pin exactly at the stop). The eyes' stereo budget: test_eye_accuracy."""
import json
import math

import numpy as np
import pytest

from robogene_head import unpowered
from robogene_head.massprops import MassProps
from robogene_head_model.params import ParameterError, load
from robogene_head.parts import eye_stops
from robogene_head.geom import distance

from param_variants import edited_file


def _point(mass, at):
    return MassProps(mass, np.array(at, dtype=float), np.zeros((3, 3)))


@pytest.mark.timeout(600)
def test_a_mass_above_the_neck_falls_and_one_below_the_tilt_axis_settles(params, tmp_path):
    """No payload: a point 1 mm in front of the head frame's axis and 60 mm up topples pitch forward (to the
    limit it leans towards: positive pitch raises the front, so down is negative), while a point hanging under
    the tilt axis, 5 mm forward of it, settles where it hangs straight down: tilt = -asin... = -atan(5/40)."""
    bare = load(edited_file(tmp_path, lambda d: d["drive_sizing"].update(payloads=[])))
    props = {"head_frame": _point(1.0, [1, 0, 60]), "eyes_tilt_link": _point(0.1, [5, 0, -40])}
    rows = {r.joint: r for r in unpowered.analyse(bare, props, {j: 1.0 for j in bare.joints})}
    pitch = bare.joints["neck_pitch"]
    assert rows["neck_pitch"].behaviour == "falls" and rows["neck_pitch"].end_deg == pytest.approx(pitch.lower)
    assert rows["neck_pitch"].hold_Nm == pytest.approx(1.5)
    assert rows["neck_yaw"].behaviour == "balanced" and rows["neck_yaw"].hold_Nm == 0
    tilt = rows["eyes_tilt"]
    # tilt turns about -y: a positive angle lifts the front, so the point 5 mm forward swings back to hang under
    assert tilt.behaviour == "settles" and tilt.hold_Nm == 0
    assert tilt.end_deg == pytest.approx(-math.degrees(math.atan2(5, 40)), abs=unpowered.STEP_DEG)


def test_the_package_reports_the_unpowered_head(fab):
    rows = {r["joint"]: r for r in json.loads((fab / "reports" / "unpowered.json").read_text())["joints"]}
    assert rows["neck_pitch"]["behaviour"] == rows["neck_roll"]["behaviour"] == "falls"
    sizing = {j["joint"]: j for j in json.loads((fab / "reports" / "drive-sizing.json").read_text())["joints"]}
    assert rows["neck_pitch"]["hold_Nm"] == pytest.approx(1.5 * sizing["neck_pitch"]["gravity_Nm"])


@pytest.mark.timeout(900)
@pytest.mark.parametrize("joint, side", [("left_eye_pan", 1), ("left_eye_pan", 0), ("right_eye_pan", 0)])
def test_the_lug_strikes_its_pin_at_the_stop(params, assembly, joint, side):
    """At the stop angle the lug touches the pin; half a degree short it is clear, two degrees past it they
    overlap: the pins stop the eye there and nowhere else in its range."""
    stop = eye_stops.stops_deg(params, joint)[side]         # side 0: the lower stop, 1: the upper
    eye = "left" if joint.startswith("left") else "right"
    pin = f"{joint}_stop_pin_{1 if side == 0 else 0}"

    def shapes(angle):
        placed = {p.part.name: p.shape for p in assembly.pose(chain={joint: angle})}
        return placed[f"{eye}_eye_cup"], placed[pin]
    inward = -1 if stop > 0 else 1
    assert distance(*shapes(stop)) < 0.01
    assert distance(*shapes(stop + inward * 0.5)) > 0.05
    cup, p = shapes(stop - inward * 2)
    assert cup.intersect(p).Volume() > 0.1
    limit = params.joints[joint].upper if stop > 0 else params.joints[joint].lower
    assert distance(*shapes(limit)) >= params.geometry("clearances").num("minimum")


@pytest.mark.timeout(900)
def test_stops_inside_the_range_are_refused(params, external, tmp_path):
    from robogene_head.parts import build_all
    path = edited_file(tmp_path, lambda d: d["homing"]["left_eye_pan"].update(stops_deg=[-56.5, 50]))
    with pytest.raises(ParameterError, match=r"homing\.left_eye_pan\.stops_deg: expected lower stop < -52\.5 and "
                                             r"upper stop > 52\.5"):
        build_all(load(path), external)
