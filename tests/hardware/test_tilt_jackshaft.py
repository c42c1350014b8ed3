# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The eye tilt's jackshaft stage (robogene_head/parts/tilt_jackshaft.py): the torque path in the parameter file is
what the CAD draws, the stage passes the torque-path check where a weakened variant (an MXL belt, a plain bore on
the jackshaft) fails, what turns in the housing keeps the minimum clearance from what stands, the bearings get
the fits of a turning shaft, and the housing slides in its slots to tension the belt."""

import pytest

from robogene_head import fits, torque_path
from robogene_head.parts import head_frame, tilt_jackshaft
from robogene_head.parts.base import loc

import jackshaft_stage
from least_distance import least_distance
from param_variants import edited


@pytest.fixture(scope="module")
def parts(params):
    return {p.name: p for p in head_frame.build(params)}


def _span_y(part):
    box = part.shape.BoundingBox()
    return box.ymin, box.ymax


def mismatches(params, parts) -> list[str]:
    """Where torque_paths.eyes_tilt and the CAD disagree (empty: they agree)."""
    return jackshaft_stage.mismatches(params, parts, tilt_jackshaft.stage(params))


def test_the_torque_path_is_what_the_cad_draws(params, parts):
    assert mismatches(params, parts) == []


def test_a_torque_path_unlike_the_cad_is_caught(params, parts, tmp_path):
    def two_screws(data):
        data["torque_paths"]["eyes_tilt"][1]["count"] = 2
    assert mismatches(edited(tmp_path, two_screws), parts) == ["clamp of 2 screws, 1 drawn over its shaft"]

    def weak_screw(data):
        data["torque_paths"]["eyes_tilt"][0]["strength_class"] = "8.8"
    assert mismatches(edited(tmp_path, weak_screw), parts) == [
        "clamp screw M2 8.8, drawn iso4762-M2x8-12.9"]


def test_the_tilt_stage_passes_every_element(params):
    """The coupling's M2 12.9 clamp on the 3 mm shaft: 0.15 x 1 x F_M x 3 mm = 0.77 N m against the 0.261 N m peak."""
    report = torque_path.analyse(params)
    tilt = [e for e in report.elements if e.joint == "eyes_tilt"]
    assert [e.element for e in tilt] == ["clamp", "clamp", "set_screw", "belt", "set_screw"]
    assert all(e.margin >= report.required for e in tilt)
    assert tilt[0].capacity_Nm == pytest.approx(0.773, abs=0.001) and tilt[1].capacity_Nm == pytest.approx(2 * 0.773, abs=0.002)
    assert tilt[3].margin == pytest.approx(2.23, abs=0.005)


@pytest.mark.parametrize("edit, weak", [
    # the stage on MXL stock again, pulleys drawn at its pitch
    (lambda data: data["geometry"]["pulleys"]["tilt"].update(belt="mxl-belt-6mm", pitch=2.032, width=8,
                                                             flange_thickness=0.6), "belt"),
    # the motor pulley on a plain bore: nothing but friction between them
    (lambda data: data["torque_paths"]["eyes_tilt"].__setitem__(
        2, {"element": "plain", "at": "gearhead", "shaft": 6, "what": "plain bore"}), "plain"),
])
def test_a_weakened_tilt_stage_fails(tmp_path, edit, weak):
    report = torque_path.analyse(edited(tmp_path, edit))
    failed = [e for e in report.failures() if e.joint == "eyes_tilt"]
    assert [e.element for e in failed] == [weak]
    with pytest.raises(torque_path.TorquePathError, match=r"eyes_tilt\[\d\] " + weak):
        torque_path.enforce(report)


TURNING = ("eyes_tilt_jackshaft", "eyes_tilt_jackshaft_spacer", "eyes_tilt_coupling", "eyes_tilt_coupling_screw_0", "eyes_tilt_coupling_screw_1",
           "eyes_tilt_motor_pulley", "eyes_tilt_motor_pulley_set_screw_0", "eyes_tilt_motor_pulley_set_screw_1")
STANDING = ("eyes_tilt_jackshaft_housing", "head_side_plate_left", "tilt_housing_screw_0", "tilt_housing_screw_1",
            "eyes_tilt_clamp_screw", "head_back_plate")


def _closest(params, parts):
    """The least distance between what turns with the jackshaft and what stands round it, over a turn."""
    lay = tilt_jackshaft.layout(params)
    pairs = []
    for angle in (0, 60, 120, 180, 240, 300):
        turn = loc(lay.x, 0, lay.z) * loc(ry=angle) * loc(-lay.x, 0, -lay.z)
        for a in TURNING:
            turned = parts[a].shape.moved(turn)
            pairs += [(turned, parts[b].shape) for b in STANDING]
    return least_distance(pairs)


def test_what_turns_in_the_housing_keeps_the_minimum_clearance(params, parts, tmp_path):
    """These turn within one link, which the interference sweep does not see: over a turn, the jackshaft, the coupling
    and its screws, the motor pulley and its set screws keep clearances.minimum from the housing, the side plate and
    the screws that stand. A cavity 1 mm narrower brings the coupling within 0.5 mm of its wall."""
    minimum = params.geometry("clearances").num("minimum")
    assert _closest(params, parts) >= minimum
    narrow = edited(tmp_path, lambda data: data["geometry"]["tilt_jackshaft"]["housing"].update(cavity=17))
    assert _closest(narrow, {p.name: p for p in head_frame.build(narrow)}) < minimum


def test_the_jackshaft_bearings_get_a_turning_shafts_fits(params, parts):
    """The belt's pull stands still in the head while the jackshaft turns: its journals are k6 (the inner rings pressed
    on), the housing's two seats H7, coaxial."""
    found = fits.find(params, list(parts.values()))
    (journal,) = found["eyes_tilt_jackshaft"]
    assert (journal.role, journal.tolerance, journal.count) == ("journal", "k6", 2)
    (seat,) = found["eyes_tilt_jackshaft_housing"]
    assert (seat.role, seat.tolerance, seat.count, seat.coaxial) == ("housing", "H7", 2, 0.02)


def test_the_housing_slides_in_its_slots_to_tension_the_belt(params, parts):
    """The side plate's slots let the housing, its screws and the jackshaft move 0.9 mm either way along x without a
    shank or the shaft touching the plate; 1.5 mm closes them."""
    plate = parts["head_side_plate_left"].shape
    moving = [parts[n] for n in ("tilt_housing_screw_0", "tilt_housing_screw_1", "eyes_tilt_jackshaft")]
    for dx in (-0.9, 0.9):
        assert all(plate.intersect(p.shape.moved(loc(dx, 0, 0))).Volume() < 1e-6 for p in moving), dx
    assert all(plate.intersect(p.shape.moved(loc(1.5, 0, 0))).Volume() > 0.01 for p in moving[:2])


def test_the_coupling_holds_enough_of_each_shaft(params, parts):
    """The gearhead's 8 mm shaft reaches 7 mm into the coupling's 8 mm half (1 mm from its face, set with a feeler
    gauge), the jackshaft 7 mm into the other."""
    lay = tilt_jackshaft.layout(params)
    c0, c1 = lay.coupling
    assert _span_y(parts["eyes_tilt_gearhead"])[1] - c0 == pytest.approx(7)
    assert (c1 - _span_y(parts["eyes_tilt_jackshaft"])[0]) == pytest.approx(7)
