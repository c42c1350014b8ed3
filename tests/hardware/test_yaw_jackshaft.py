# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The neck yaw's jackshaft stage (robogene_head/parts/yaw_jackshaft.py): the stage stands on the head floor, its
jackshaft pointing down through it at geometry.yaw_jackshaft.axis; the torque path in the parameter file is what the
CAD draws and passes where a weakened variant (the old MXL belt, a plain bore) fails; what turns in the housing keeps
the minimum clearance from what stands; the housing slides along the belt in the floor's slots; the flange stands
ahead of the axis only, clear of the right side plate."""
import math

import numpy as np
import pytest

from robogene_head import fits, torque_path
from robogene_head.geom import distance, exact_bounds
from robogene_head.parts import head_frame, jackshaft, yaw_jackshaft
from robogene_head.parts.base import loc

import jackshaft_stage
from param_variants import edited

J = "neck_yaw"


@pytest.fixture(scope="module")
def parts(params):
    return {p.name: p for p in head_frame.build(params)}


def test_the_stage_points_down_through_the_floor_at_its_axis(params, parts):
    """The jackshaft's axis is vertical at (x, y) of geometry.yaw_jackshaft.axis; the housing stands on the floor's
    top face, the motor pulley hangs under its underside (pulleys.plate_gap below it)."""
    x, y = params.geometry("yaw_jackshaft").vec("axis", 2)
    floor = params.geometry("head", "floor")
    (x0, y0, z0), (x1, y1, z1) = exact_bounds(parts[f"{J}_jackshaft"].shape)
    assert ((x0 + x1) / 2, (y0 + y1) / 2) == pytest.approx((x, y), abs=1e-6)
    assert z1 - z0 > 40
    (_, _, hz0), _ = exact_bounds(parts[f"{J}_jackshaft_housing"].shape)
    assert hz0 == pytest.approx(0, abs=1e-6)
    _, (_, _, pz1) = exact_bounds(parts[f"{J}_motor_pulley"].shape)
    assert pz1 == pytest.approx(-floor.num("thickness") - params.geometry("pulleys").num("plate_gap"), abs=1e-6)
    # the motor's stack stands above it, on the same axis
    (mx0, my0, mz0), (mx1, my1, _) = exact_bounds(parts[f"{J}_motor"].shape)
    assert ((mx0 + mx1) / 2, (my0 + my1) / 2) == pytest.approx((x, y), abs=1e-6) and mz0 > 0


def test_the_torque_path_is_what_the_cad_draws(params, parts):
    assert jackshaft_stage.mismatches(params, parts, yaw_jackshaft.stage(params)) == []


def test_a_torque_path_unlike_the_cad_is_caught(params, parts, tmp_path):
    def two_screws(data):
        data["torque_paths"][J][0]["count"] = 2
    stage = yaw_jackshaft.stage(params)
    assert jackshaft_stage.mismatches(edited(tmp_path, two_screws), parts, stage) == [
        "clamp of 2 screws, 1 drawn over its shaft"]

    def small_bore(data):
        data["torque_paths"][J][1]["shaft"] = 5
    assert jackshaft_stage.mismatches(edited(tmp_path, small_bore), parts, stage) == [
        "clamp on 5 mm, the coupling's bore is 6"]


def test_the_yaw_stage_passes_every_element(params):
    """The coupling's M2 12.9 clamp on the 22/7's 4 mm shaft: 0.15 x 1 x F_M x 4 mm = 1.03 N m against the 0.373 N m
    the 550 mA limit lets the drive put through; the XL belt 0.581 N m at the 14T pulley, margin 1.56."""
    report = torque_path.analyse(params)
    yaw = [e for e in report.elements if e.joint == J]
    assert [e.element for e in yaw] == jackshaft_stage.ELEMENTS
    assert all(e.margin >= report.required for e in yaw)
    assert yaw[0].capacity_Nm == pytest.approx(4 / 3 * 0.773, abs=0.002)
    assert yaw[0].peak_Nm == pytest.approx(0.373, abs=0.001)
    assert yaw[3].margin == pytest.approx(1.56, abs=0.005)


@pytest.mark.parametrize("edit, weak", [
    # the stage on the old MXL stock, pulleys drawn at its pitch
    (lambda data: data["geometry"]["pulleys"]["yaw"].update(belt="mxl-belt-6mm", pitch=2.032, width=8,
                                                            flange_thickness=0.6), ["belt"]),
    # the motor pulley on a plain bore: nothing but friction between them
    (lambda data: data["torque_paths"][J].__setitem__(
        2, {"element": "plain", "at": "gearhead", "shaft": 6, "what": "plain bore"}), ["plain"]),
    # the board's old 1200 mA limit: more than the XL belt and the coupling's clamp on the 4 mm shaft carry with the
    # margin
    (lambda data: data["motor_control"]["joints"][J].update(current_limit=1200), ["clamp", "belt"]),
])
def test_a_weakened_yaw_stage_fails(tmp_path, edit, weak):
    report = torque_path.analyse(edited(tmp_path, edit))
    failed = [e for e in report.failures() if e.joint == J]
    assert [e.element for e in failed] == weak
    with pytest.raises(torque_path.TorquePathError, match=J + r"\[\d\] " + weak[0]):
        torque_path.enforce(report)


TURNING = (f"{J}_jackshaft", f"{J}_jackshaft_spacer", f"{J}_coupling", f"{J}_coupling_screw_0", f"{J}_coupling_screw_1",
           f"{J}_motor_pulley", f"{J}_motor_pulley_set_screw_0", f"{J}_motor_pulley_set_screw_1")
STANDING = (f"{J}_jackshaft_housing", "head_floor", "yaw_housing_screw_0", "yaw_housing_screw_1", f"{J}_clamp_screw")


def _closest(params, parts, turning=TURNING, standing=STANDING):
    """The least distance between what turns with the jackshaft and what stands round it, over a turn."""
    x, y = params.geometry("yaw_jackshaft").vec("axis", 2)
    least = math.inf
    for angle in (0, 60, 120, 180, 240, 300):
        turn = loc(x, y, 0) * loc(rz=angle) * loc(-x, -y, 0)
        for a in turning:
            for b in standing:
                least = min(least, distance(parts[a].shape.moved(turn), parts[b].shape))
    return least


@pytest.mark.timeout(900)
def test_what_turns_in_the_housing_keeps_the_minimum_clearance(params, parts, tmp_path):
    """Within one link, which the interference sweep does not see: over a turn the jackshaft, the coupling and its
    screws, the motor pulley and its set screws keep clearances.minimum from the housing, the floor and the screws
    that stand. A cavity 1 mm narrower brings the coupling within 0.5 mm of its wall."""
    minimum = params.geometry("clearances").num("minimum")
    assert _closest(params, parts) >= minimum
    narrow = edited(tmp_path, lambda data: data["geometry"]["yaw_jackshaft"]["housing"].update(cavity=17))
    assert _closest(narrow, {p.name: p for p in head_frame.build(narrow)}, (f"{J}_coupling",),
                    (f"{J}_jackshaft_housing",)) < minimum


def test_the_jackshaft_bearings_get_a_turning_shafts_fits(params, parts):
    found = fits.find(params, list(parts.values()))
    (journal,) = found[f"{J}_jackshaft"]
    assert (journal.role, journal.tolerance, journal.count) == ("journal", "k6", 2)
    (seat,) = found[f"{J}_jackshaft_housing"]
    assert (seat.role, seat.tolerance, seat.count, seat.coaxial) == ("housing", "H7", 2, 0.02)


def _along_belt(params) -> np.ndarray:
    x, y = params.geometry("yaw_jackshaft").vec("axis", 2)
    return -np.array([x, y]) / math.hypot(x, y)


def test_the_housing_slides_along_the_belt_in_the_floors_slots(params, parts):
    """The floor's slots let the housing's screws and the jackshaft move 0.9 mm either way along the belt without a
    shank or the shaft touching the floor; 1.5 mm closes them, and so does 0.9 mm across the belt."""
    floor = parts["head_floor"].shape
    moving = [parts[n] for n in ("yaw_housing_screw_0", "yaw_housing_screw_1", f"{J}_jackshaft")]
    u = _along_belt(params)
    for d in (-0.9, 0.9):
        assert all(floor.intersect(p.shape.moved(loc(*(d * u), 0))).Volume() < 1e-6 for p in moving), d
    assert all(floor.intersect(p.shape.moved(loc(*(1.5 * u), 0))).Volume() > 0.01 for p in moving[:2])
    across = np.array([-u[1], u[0]])
    assert all(floor.intersect(p.shape.moved(loc(*(0.9 * across), 0))).Volume() > 0.01 for p in moving[:2])


def test_the_tensioned_housing_clears_the_right_side_plate(params, parts, tmp_path):
    """The flange stands ahead of the axis only: the housing's back corner is the nearest to the right side plate,
    and still clear of it with the housing slid the 0.86 mm away from the yaw axis that the 35-tooth belt needs
    (45.46 mm centres, drawn at 44.6). Drawn from behind the axis, as the tilt's, the flange runs into the plate."""
    housing, plate = parts[f"{J}_jackshaft_housing"].shape, parts["head_side_plate_right"].shape
    tension = loc(*(-0.86 * _along_belt(params)), 0)
    assert distance(housing.moved(tension), plate) > 0.5
    behind = edited(tmp_path, lambda data: data["geometry"]["yaw_jackshaft"]["housing"].update(flange_back=13))
    stage = yaw_jackshaft.stage(behind)
    assert plate.intersect(jackshaft.placed(stage, jackshaft.housing(behind, stage))).Volume() > 1


def test_the_coupling_holds_enough_of_each_shaft(params, parts):
    """The 22/7's 10 mm shaft reaches 8 mm into the coupling's 8 mm half (2 mm from its face, set with a feeler
    gauge), the jackshaft 6 mm into the other."""
    stage = yaw_jackshaft.stage(params)
    lay = yaw_jackshaft.layout(params)
    c0, c1 = lay.coupling
    assert jackshaft_stage.span_y(stage, parts[f"{J}_gearhead"])[1] - c0 == pytest.approx(8)
    assert c1 - jackshaft_stage.span_y(stage, parts[f"{J}_jackshaft"])[0] == pytest.approx(6)
