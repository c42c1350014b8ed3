# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""A jackshaft's bearings in the bearing-load and bearing-arrangement checks (robogene_head/bearing_loads.py,
bearing_arrangement.py, jackshafts.py): the belt's pull at the drive's peak torque, split by statics between the two
628/6 with the pulley overhanging the fixed one, each row against C0; one fixed bearing (both rings held both ways: the
collar and the spacer sleeve, the land and the side plate) and one floating (its outer ring with room to slide, its
inner ring against the collar), failing on the old design and on broken variants; a jackshaft is found from the parts'
data, so the yaw's, the same stage turned to point down through the head floor, is picked up with no new code."""
import math

import numpy as np
import pytest

from robogene_head import bearing_arrangement as arrangement
from robogene_head import bearing_loads, geom, jackshafts, torque_path
from robogene_head.geom import exact_bounds
from robogene_head.parts import head_frame, jackshaft, tilt_jackshaft
from robogene_head.parts.base import Part, loc
from robogene_head_model.params import ParameterError

from param_variants import edited


@pytest.fixture(scope="module")
def parts(params):
    return head_frame.build(params)


def _centre(part, axis):
    lo, hi = exact_bounds(part.shape)
    return (lo[axis] + hi[axis]) / 2


@pytest.mark.parametrize("joint, axis", [("eyes_tilt", 1), ("neck_yaw", 2)])
def test_the_belt_pull_is_shared_by_statics(params, parts, joint, axis):
    """Pull = (1 + 2 x 0.3) x T / r: the peak torque (0.261 N m on the tilt, 0.373 on the yaw) on the 14T XL pulley's
    11.32 mm pitch radius; the belt's plane is the belt envelope's middle, the bearings' places their envelopes'
    middles along the jackshaft's axis (the tilt's along y, the yaw's along z: the CAD, not the check's frames)."""
    loads, problems, pulls = bearing_loads.jackshaft_loads(params, parts)
    assert problems == [] and len(pulls) == 2
    [pull] = [p for p in pulls if p.shaft == f"{joint}_jackshaft"]
    by_name = {p.name: p for p in parts}
    torque = torque_path.peak(params, joint).at_gearhead
    force = 1.6 * torque / (14 * 5.08 / math.pi / 2 * 1e-3)
    assert pull.pull_N == pytest.approx(force, rel=1e-9)
    belt = _centre(by_name[f"{joint}_belt"], axis)
    fixed, floating = (_centre(by_name[f"{joint}_jackshaft_bearing_{n}"], axis) for n in ("fixed", "floating"))
    # moments about the floating bearing: the fixed one carries the pull times its lever over the bearings' span
    expect = {f"{joint}_jackshaft_bearing_fixed": force * (belt - floating) / (fixed - floating),
              f"{joint}_jackshaft_bearing_floating": force * (belt - fixed) / (fixed - floating)}
    rows = {b.bearing: b for b in loads if b.bearing.startswith(joint)}
    assert set(rows) == set(expect)
    for name, radial in expect.items():
        assert rows[name].radial_N == pytest.approx(radial, rel=1e-6)
        assert rows[name].axial_N == 0 and rows[name].p0_N == rows[name].radial_N
        assert rows[name].safety == pytest.approx(350 / radial, rel=1e-6)
    # the pulley overhangs the fixed bearing: it carries the whole pull and what the floating one pulls the other way
    assert rows[f"{joint}_jackshaft_bearing_fixed"].radial_N == pytest.approx(
        force + rows[f"{joint}_jackshaft_bearing_floating"].radial_N, rel=1e-9)
    assert all(b.safety >= bearing_loads.required_safety(params) for b in loads)


def test_a_weaker_bearing_fails_the_check(tmp_path, parts):
    """The 628/6 at C0 0.2 kN: the fixed one (109 N) falls to 1.8, under the required 2."""
    weak = edited(tmp_path, lambda data: data["purchased"]["skf-628-6-2Z"].update(static_load_rating_kN=0.2))
    loads, _, _ = bearing_loads.jackshaft_loads(weak, parts)
    report = bearing_loads.Report(bearing_loads.required_safety(weak), loads, [])
    assert not report.ok
    with pytest.raises(bearing_loads.BearingLoadError, match=r"eyes_tilt_jackshaft_bearing_fixed \(1\.8"):
        bearing_loads.enforce(report)


def test_the_yaw_jackshaft_is_picked_up(params, parts):
    """The yaw's stage, drawn by the same module and pointing down through the floor, is found with no new code:
    driven by the yaw's gearhead on its axis, its pulley the one that turns with it, its bearings along its axis
    from the gearhead's end (the floating one above the fixed one)."""
    found = jackshafts.find(params, parts)
    assert [(j.shaft, j.joint, j.pulley) for j in found] == [
        ("neck_yaw_jackshaft", "neck_yaw", "neck_yaw_motor_pulley"),
        ("eyes_tilt_jackshaft", "eyes_tilt", "eyes_tilt_motor_pulley")]
    yaw = found[0]
    assert np.allclose(np.abs(yaw.axis), [0, 0, 1])
    # in the link frame, which is the world's turned by nothing at the zero pose: along the axis from the gearhead
    by_name = {p.name: p for p in parts}
    places = [yaw.along(np.array(by_name[b].shape.Center().toTuple())) for b in yaw.bearings]
    assert yaw.bearings == ["neck_yaw_jackshaft_bearing_floating", "neck_yaw_jackshaft_bearing_fixed"]
    assert places == sorted(places)


def _shaft_result(report, name="eyes_tilt_jackshaft"):
    return next(j for j in report.joints if j.joint == name)


def test_the_jackshaft_has_a_fixed_and_a_floating_bearing(params, parts):
    report = arrangement.analyse(params, parts)
    assert report.ok, arrangement.format_report(report)
    shaft = _shaft_result(report)
    assert (shaft.arrangement, shaft.fixed) == ("fixed + floating", "eyes_tilt_jackshaft_bearing_fixed")
    fixed, floating = ({b.bearing: b for b in shaft.bearings}[f"eyes_tilt_jackshaft_bearing_{n}"]
                       for n in ("fixed", "floating"))
    # stops found on what turns with the shaft (inner ring) and what stands with the housing (outer ring)
    assert {fixed.inner.minus.stop, fixed.inner.plus.stop} == {"eyes_tilt_jackshaft", "eyes_tilt_jackshaft_spacer"}
    assert {fixed.outer.minus.stop, fixed.outer.plus.stop} == {"eyes_tilt_jackshaft_housing", "head_side_plate_left"}
    assert floating.role == "floating" and floating.outer.slides and not floating.inner.slides
    # towards the land it has float_room, 0.5 mm, against the 0.2 it needs (ISO 2768-m over 8.5 mm and its growth)
    assert floating.outer.plus.stop == "eyes_tilt_jackshaft_housing" and floating.outer.plus.gap == pytest.approx(0.5)
    assert floating.required == pytest.approx(0.2 + (23.4e-6 - 11.6e-6) * 40 * 8.5, abs=1e-4)   # steel in aluminium, both warm
    assert floating.outer.minus.gap is None
    assert floating.inner.plus.gap == 0 and floating.inner.plus.stop == "eyes_tilt_jackshaft"


def test_the_old_jackshaft_design_fails(tmp_path, params, parts):
    """Last session's stage: no spacer (the fixed bearing's inner ring held outboard by its press fit alone) and the
    floating bearing's outer ring seated against the land (float_room at its least here, 0.01 mm)."""
    old = edited(tmp_path, lambda data: data["geometry"]["tilt_jackshaft"].update(float_room=0.01))
    old_parts = [p for p in head_frame.build(old) if p.name != "eyes_tilt_jackshaft_spacer"]
    failures = [f for f in arrangement.analyse(old, old_parts).failures if f.startswith("eyes_tilt_jackshaft")]
    assert failures[0].startswith("eyes_tilt_jackshaft: no bearing locates the shaft both ways (no fixed bearing): ")
    assert "eyes_tilt_jackshaft_bearing_fixed is one way" in failures[0]
    assert "eyes_tilt_jackshaft_bearing_floating is floating" in failures[0]
    with pytest.raises(arrangement.BearingArrangementError, match="eyes_tilt_jackshaft: no bearing locates"):
        arrangement.enforce(arrangement.analyse(old, old_parts))


def test_a_floating_outer_ring_against_the_land_fails(tmp_path):
    tight = edited(tmp_path, lambda data: data["geometry"]["tilt_jackshaft"].update(float_room=0.1))
    [failure] = arrangement.analyse(tight, head_frame.build(tight)).failures
    assert failure.startswith("eyes_tilt_jackshaft: eyes_tilt_jackshaft_bearing_floating must float, but its outer ring "
                              "(H7, the sliding one) has 0.10 mm of room towards +y to eyes_tilt_jackshaft_housing: "
                              "it needs 0.20 mm")


def test_a_floating_outer_ring_also_held_fails(params, parts):
    """A cover ring in the housing against the floating bearing's inboard face: it then locates the shaft one way."""
    b = next(p for p in parts if p.name == "eyes_tilt_jackshaft_bearing_floating")
    ring = Part("cover", "cover", b.link, "machined", geom.tube("z", 13, 10, -1, 0), b.placement,
                material="aluminium-6082")
    [failure] = arrangement.analyse(params, parts + [ring]).failures
    assert failure == ("eyes_tilt_jackshaft: eyes_tilt_jackshaft_bearing_floating locates the shaft one way (towards -y) "
                       "besides the fixed bearing: it must float")


def test_the_yaw_jackshaft_is_checked_too(params, parts):
    """Its fixed bearing at the floor: inner ring between the collar and the spacer sleeve, outer ring between the
    housing's land and the floor's top face; the floating one above it with its float room."""
    report = arrangement.analyse(params, parts)
    assert report.ok, arrangement.format_report(report)
    assert [(j.joint, j.fixed) for j in report.joints][-2:] == [
        ("neck_yaw_jackshaft", "neck_yaw_jackshaft_bearing_fixed"),
        ("eyes_tilt_jackshaft", "eyes_tilt_jackshaft_bearing_fixed")]
    fixed = {b.bearing: b for b in _shaft_result(report, "neck_yaw_jackshaft").bearings}["neck_yaw_jackshaft_bearing_fixed"]
    assert {fixed.inner.minus.stop, fixed.inner.plus.stop} == {"neck_yaw_jackshaft", "neck_yaw_jackshaft_spacer"}
    assert {fixed.outer.minus.stop, fixed.outer.plus.stop} == {"neck_yaw_jackshaft_housing", "head_floor"}


def test_a_float_room_that_eats_the_land_is_refused(tmp_path):
    bad = edited(tmp_path, lambda data: data["geometry"]["tilt_jackshaft"].update(float_room=3.5))
    with pytest.raises(ParameterError, match=r"geometry\.tilt_jackshaft\.float_room: 3\.5 leaves no land"):
        jackshaft.housing(bad, tilt_jackshaft.stage(bad))
