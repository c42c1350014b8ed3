# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""A jackshaft's bearings in the bearing-load and bearing-arrangement checks (robogene_head/bearing_loads.py,
bearing_arrangement.py, jackshafts.py): the belt's pull at the drive's peak torque, split by statics between the two
628/6 with the pulley overhanging the fixed one, each row against C0; one fixed bearing (both rings held both ways: the
collar and the spacer sleeve, the land and the side plate) and one floating (its outer ring with room to slide, its
inner ring against the collar), failing on the old design and on broken variants; a jackshaft is found from the parts'
data, so a second one in the same shape is picked up with no new code."""
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


def _centre_y(part):
    lo, hi = exact_bounds(part.shape)
    return (lo[1] + hi[1]) / 2


def test_the_belt_pull_is_shared_by_statics(params, parts):
    """Pull = (1 + 2 x 0.3) x T / r: 0.261 N m on the 14T XL pulley's 11.32 mm pitch radius; the belt's plane is the
    belt envelope's middle, the bearings' places their envelopes' middles (the CAD, not the check's frames)."""
    loads, problems, [pull] = bearing_loads.jackshaft_loads(params, parts)
    assert problems == []
    by_name = {p.name: p for p in parts}
    torque = torque_path.peak(params, "eyes_tilt").at_gearhead
    force = 1.6 * torque / (14 * 5.08 / math.pi / 2 * 1e-3)
    assert pull.pull_N == pytest.approx(force, rel=1e-9)
    belt = _centre_y(by_name["eyes_tilt_belt"])
    fixed, floating = (_centre_y(by_name[f"eyes_tilt_jackshaft_bearing_{n}"]) for n in ("fixed", "floating"))
    # moments about the floating bearing: the fixed one carries the pull times its lever over the bearings' span
    expect = {"eyes_tilt_jackshaft_bearing_fixed": force * (belt - floating) / (fixed - floating),
              "eyes_tilt_jackshaft_bearing_floating": force * (belt - fixed) / (fixed - floating)}
    rows = {b.bearing: b for b in loads}
    assert set(rows) == set(expect)
    for name, radial in expect.items():
        assert rows[name].radial_N == pytest.approx(radial, rel=1e-6)
        assert rows[name].axial_N == 0 and rows[name].p0_N == rows[name].radial_N
        assert rows[name].safety == pytest.approx(350 / radial, rel=1e-6)
    # the pulley overhangs the fixed bearing: it carries the whole pull and what the floating one pulls the other way
    assert rows["eyes_tilt_jackshaft_bearing_fixed"].radial_N == pytest.approx(
        force + rows["eyes_tilt_jackshaft_bearing_floating"].radial_N, rel=1e-9)
    assert all(b.safety >= bearing_loads.required_safety(params) for b in loads)


def test_a_weaker_bearing_fails_the_check(tmp_path, parts):
    """The 628/6 at C0 0.2 kN: the fixed one (109 N) falls to 1.8, under the required 2."""
    weak = edited(tmp_path, lambda data: data["purchased"]["skf-628-6-2Z"].update(static_load_rating_kN=0.2))
    loads, _, _ = bearing_loads.jackshaft_loads(weak, parts)
    report = bearing_loads.Report(bearing_loads.required_safety(weak), loads, [])
    assert not report.ok
    with pytest.raises(bearing_loads.BearingLoadError, match=r"eyes_tilt_jackshaft_bearing_fixed \(1\.8"):
        bearing_loads.enforce(report)


def _copied_stage(params, parts, dx):
    """The tilt's jackshaft stage again, `dx` along x, its gearhead renamed as the yaw's (the finder names the driving
    joint by its gearhead on the shaft's axis); the real yaw gearhead left out."""
    names = {"eyes_tilt_jackshaft_housing", "eyes_tilt_jackshaft", "eyes_tilt_jackshaft_bearing_fixed",
             "eyes_tilt_jackshaft_spacer", "eyes_tilt_coupling_screw_0", "eyes_tilt_coupling_screw_1",
             "eyes_tilt_jackshaft_bearing_floating", "eyes_tilt_coupling", "eyes_tilt_motor_pulley",
             "eyes_tilt_motor_pulley_set_screw_0", "eyes_tilt_motor_pulley_set_screw_1", "eyes_tilt_gearhead"}
    copies = []
    for p in parts:
        if p.name in names:
            name = "neck_yaw_gearhead" if p.name == "eyes_tilt_gearhead" else "copy_" + p.name
            copies.append(Part(name, p.design, p.link, p.kind, p.local, loc(dx) * p.placement, material=p.material,
                               mass=p.mass, turning=p.turning))
    # the side plate with the stage's passage and fixings there too
    plate = next(p for p in parts if p.name == "head_side_plate_left")
    holed = Part(plate.name, plate.design, plate.link, plate.kind,
                 geom.cut(plate.shape, *[t.moved(loc(dx)) for t in tilt_jackshaft.side_plate_tools(params)]),
                 material=plate.material)
    return [holed if p.name == plate.name else p for p in parts if p.name != "neck_yaw_gearhead"] + copies


def test_a_second_jackshaft_is_picked_up(params, parts):
    found = jackshafts.find(params, _copied_stage(params, parts, 60.0))
    assert [(j.shaft, j.joint, j.pulley) for j in found] == [
        ("eyes_tilt_jackshaft", "eyes_tilt", "eyes_tilt_motor_pulley"),
        ("copy_eyes_tilt_jackshaft", "neck_yaw", "copy_eyes_tilt_motor_pulley")]
    assert found[1].bearings == ["copy_eyes_tilt_jackshaft_bearing_floating", "copy_eyes_tilt_jackshaft_bearing_fixed"]
    assert np.allclose(found[1].origin - found[0].origin, [60, 0, 0])


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
    # towards the land it has float_room, 0.5 mm, against the 0.2 it needs (ISO 2768-m over 8.5 mm and growth)
    assert floating.outer.plus.stop == "eyes_tilt_jackshaft_housing" and floating.outer.plus.gap == pytest.approx(0.5)
    assert floating.required == pytest.approx(0.2 + 23.1e-6 * 20 * 8.5, abs=1e-3)
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


def test_a_second_jackshaft_is_checked_too(params, parts):
    report = arrangement.analyse(params, _copied_stage(params, parts, 60.0))
    assert report.ok, arrangement.format_report(report)
    assert [(j.joint, j.fixed) for j in report.joints][-2:] == [
        ("eyes_tilt_jackshaft", "eyes_tilt_jackshaft_bearing_fixed"),
        ("copy_eyes_tilt_jackshaft", "copy_eyes_tilt_jackshaft_bearing_fixed")]


def test_a_float_room_that_eats_the_land_is_refused(tmp_path):
    bad = edited(tmp_path, lambda data: data["geometry"]["tilt_jackshaft"].update(float_room=3.5))
    with pytest.raises(ParameterError, match=r"geometry\.tilt_jackshaft\.float_room: 3\.5 leaves no land"):
        jackshaft.housing(bad, tilt_jackshaft.stage(bad))
