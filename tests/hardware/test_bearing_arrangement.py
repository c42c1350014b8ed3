# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""One fixed and one floating bearing per shaft, measured in the CAD (robogene_head/bearing_arrangement.py): the
present design passes (pitch and roll float their 61800s against the gearheads' output bearings, the tilt has its
fixed and its floating 626, yaw its cross-located pair); the check fails, naming the joint and the bearing, on a 61800
clamped again in its housing, a floating ring with no room, both 626 fixed, a tilt without a fixed bearing, a gearhead
off the shaft's axis, a floating ring with a tight fit, and a shim that reaches over a bearing's seal or shield (the
yaw's old DIN 988 15 x 21 shims on the 61802s' inner rings; the tilt's old DIN 988 13 x 19 on the 626's outer ring,
whose face starts at D2 16.5; a shim with too small a bore on an outer ring without D2, against the pitch circle)."""
import json

import numpy as np
import pytest

from robogene_head import bearing_arrangement as arrangement
from robogene_head import geom, kinematics, thermal_growth
from robogene_head.parts import eyes, head_frame, joint_encoders, neck, purchased
from robogene_head.parts.base import Part, loc

from param_variants import edited
from robogene_head_model.params import ParameterError


def _parts(params):
    return neck.build(params) + head_frame.build(params) + eyes.build(params) + joint_encoders.build(params)


@pytest.fixture(scope="module")
def parts(params):
    return _parts(params)


@pytest.fixture(scope="module")
def report(params, parts):
    return arrangement.analyse(params, parts)


def _joint(report, name):
    return next(j for j in report.joints if j.joint == name)


def _bearing(report, name):
    return next(b for j in report.joints for b in j.bearings if b.bearing == name)


def test_the_design_has_one_fixed_and_one_floating_bearing_per_shaft(report):
    assert report.ok, arrangement.format_report(report)
    assert [(j.joint, j.arrangement, j.fixed) for j in report.joints] == [
        ("neck_pitch", "gearhead + floating", "neck_pitch_gearhead"),
        ("neck_roll", "gearhead + floating", "neck_roll_gearhead"),
        ("neck_yaw", "cross-located", "neck_yaw_bearing_lower + neck_yaw_bearing_upper"),
        ("eyes_tilt", "fixed + floating", "eyes_tilt_bearing_right"),
        ("neck_yaw_jackshaft", "fixed + floating", "neck_yaw_jackshaft_bearing_fixed"),
        ("eyes_tilt_jackshaft", "fixed + floating", "eyes_tilt_jackshaft_bearing_fixed")]


@pytest.mark.parametrize("name, seat", [("neck_pitch_bearing_right", "neck_upright_right"),
                                        ("neck_roll_bearing_front", "neck_pitch_front_lug")])
def test_the_61800s_float_on_their_outer_rings(report, name, seat):
    """Inner ring tight (k6) against the journal's collar; outer ring sliding (H7) with no stop within reach of the
    room it needs on either side."""
    b = _bearing(report, name)
    assert b.role == "floating" and b.stops_shaft == []
    assert b.inner.tolerance == "k6" and not b.inner.slides
    assert [s.gap for s in (b.inner.minus, b.inner.plus)].count(0.0) == 1
    assert b.outer.seat == seat and b.outer.tolerance == "H7" and b.outer.slides
    for side in (b.outer.minus, b.outer.plus):
        assert side.gap is None or side.gap >= b.required
    # room each way: an aluminium stage 20 K warmer than its aluminium housing over the span plus ISO 2768-m on the span
    # (30..120 mm: 0.3); warming both together grows nothing against the other
    assert b.required == pytest.approx(23.4e-6 * 20 * b.span + 0.3, abs=1e-3)
    assert b.growth == "aluminium-6082 shaft in aluminium-6082 housing, shaft 20 K warmer governs"


@pytest.mark.parametrize("joint", ["neck_yaw_jackshaft", "eyes_tilt_jackshaft"])
def test_a_steel_jackshaft_floats_by_its_own_growth(report, joint):
    """The jackshafts are steel in aluminium housings: as both warm the housing grows away from the shaft, by more than
    the shaft 20 K warmer grows (11.6 against 23.4 um/m/K, 40 K): that case governs."""
    b = _bearing(report, f"{joint}_bearing_floating")
    assert b.growth == "steel shaft in aluminium-6082 housing, both warmed 40 K governs"
    assert b.required == pytest.approx((23.4e-6 - 11.6e-6) * 40 * b.span + 0.2, abs=1e-3)


def test_the_worst_thermal_case_by_material(params):
    same = thermal_growth.differential(params, ("s", "aluminium-6082"), ("h", "aluminium-6082"), 100)
    assert same.governs == "shaft 20 K warmer" and same.mm == pytest.approx(23.4e-6 * 20 * 100)
    assert [mm for _, mm in same.cases][1] == 0
    steel = thermal_growth.differential(params, ("s", "steel"), ("h", "aluminium-6082"), 100)
    assert [round(mm, 6) for _, mm in steel.cases] == [0.0232, -0.0472, -0.024]
    assert steel.governs == "both warmed 40 K" and steel.mm == pytest.approx(0.0472)
    with pytest.raises(ParameterError, match=r"bearing_arrangement\.expansion: no coefficient for 'petg-printed', the "
                                             r"material of s"):
        thermal_growth.differential(params, ("s", "petg-printed"), ("h", "aluminium-6082"), 100)


def test_a_steel_jackshaft_without_room_for_its_own_growth_fails(tmp_path):
    """A head that warms 120 K and a yaw jackshaft whose floating ring has 0.205 mm to the land: an aluminium shaft
    20 K warmer than its housing (the old rule, whatever the shaft) would need 0.204 mm; the steel shaft in its
    aluminium housing, both warmed, needs 0.212."""
    def edit(d):
        d["bearing_arrangement"]["temperature_rise"] = 120
        d["geometry"]["yaw_jackshaft"]["float_room"] = 0.205
    params = edited(tmp_path, edit)
    report = arrangement.analyse(params, _parts(params))
    [failure] = report.failures
    assert failure.startswith("neck_yaw_jackshaft: neck_yaw_jackshaft_bearing_floating must float, but its outer ring "
                              "(H7, the sliding one) has 0.20 mm of room towards -z to neck_yaw_jackshaft_housing: it "
                              "needs 0.21 mm (0.012 of growth over 8.5 mm, steel shaft in aluminium-6082 housing, both "
                              "warmed 120 K governs, + 0.2 ISO 2768-m)"), failure


def test_the_tilt_has_a_fixed_and_a_floating_626(report):
    right, left = _bearing(report, "eyes_tilt_bearing_right"), _bearing(report, "eyes_tilt_bearing_left")
    assert right.role == "fixed" and sorted(right.stops_shaft) == ["+axis", "-axis"]
    assert {right.inner.minus.stop, right.inner.plus.stop} == {"eyes_tilt_frame", "eyes_tilt_clip"}
    # the outer ring between the plate's shoulder and the spacer ring (no shim in the stack: the spacer is the stop)
    assert {right.outer.minus.stop, right.outer.plus.stop} == {"head_side_plate_right", "eyes_tilt_bearing_spacer"}
    assert right.shims == [] and not right.outer.minus.through and not right.outer.plus.through
    assert left.role == "floating" and left.outer.minus.gap is None and left.outer.plus.gap is None


def test_yaw_is_cross_located(report):
    lower, upper = _bearing(report, "neck_yaw_bearing_lower"), _bearing(report, "neck_yaw_bearing_upper")
    assert lower.role == upper.role == "one way"
    assert lower.outer.tolerance == "M7" and not lower.outer.slides and lower.inner.slides
    # each inner ring on its spacer ring, which bears on the ring's face alone (no shim in the stack)
    assert (lower.inner.minus.stop, upper.inner.plus.stop) == ("neck_yaw_spacer_lower", "neck_yaw_spacer_upper")
    assert lower.shims == upper.shims == []


def test_no_shim_bears_on_a_bearing(report):
    """The shims beside bearings are all turned spacer rings now (the yaw's and the tilt's): none is left for
    shim_faces to judge, and the report prints none."""
    assert [s for j in report.joints for b in j.bearings for s in b.shims] == []
    assert "    shim " not in arrangement.format_report(report)


def test_the_old_din988_shims_on_the_yaw_reach_over_the_seals(tmp_path):
    """The yaw as it was: a DIN 988 15 x 21 shim where each spacer ring is, on the 61802's inner ring, whose face is
    17.5 across: the shim lies on the seal, which turns with the outer ring while the shim stands with the shaft."""
    params = edited(tmp_path, lambda d: d["purchased"].update(
        {"din988-15x21x1": {"kind": "shim", "bore": 15, "outside": 21, "thickness": 1.0, "mass": 0.0013}}))
    parts = _parts(params)
    spacers = [p for p in parts if p.name.startswith("neck_yaw_spacer_")]
    assert len(spacers) == 2
    shims = [purchased.shim(params, p.name.replace("spacer", "shim"), "din988-15x21x1", p.link, p.placement)
             for p in spacers]
    report = _analyse(params, parts, shims, {p.name for p in spacers})
    assert report.failures == [
        f"neck_yaw: neck_yaw_shim_{which} (din988-15x21x1, 21 across) bears on neck_yaw_bearing_{which}'s inner ring, "
        f"whose face is 17.5 across (skf-61802-2RS): it reaches over the seal or shield; take a shim no more than 17.5 "
        f"across" for which in ("lower", "upper")]
    # the shims are looked through: the DIN 471 rings beyond them still locate the inner rings
    lower = _bearing(report, "neck_yaw_bearing_lower")
    assert lower.role == "one way" and lower.inner.minus.stop == "neck_yaw_ring_lower"
    assert lower.inner.minus.through == ("neck_yaw_shim_lower",) and lower.inner.minus.shim_gap == 0.0
    with pytest.raises(arrangement.BearingArrangementError, match="neck_yaw_shim_lower .* reaches over the seal"):
        arrangement.enforce(report)


def _tilt_shim(params, key):
    """The design's parts with a shim of `key` where the fixed tilt bearing's spacer ring is."""
    parts = _parts(params)
    [spacer] = [p for p in parts if p.name == "eyes_tilt_bearing_spacer"]
    shim = purchased.shim(params, "eyes_tilt_bearing_shim", key, spacer.link, spacer.placement)
    return [p for p in parts if p is not spacer] + [shim]


DIN988_13X19 = {"kind": "shim", "bore": 13, "outside": 19, "thickness": 1.0, "mass": 0.0012}


def test_the_old_din988_shim_on_the_tilt_reaches_over_the_shield(tmp_path):
    """The tilt as it was: a DIN 988 13 x 19 shim where the spacer ring is, on the fixed 626's outer ring, whose face
    starts at D2 16.5 (SKF): its 13 mm bore lies on the shield, which it would press onto the balls' cage."""
    params = edited(tmp_path, lambda d: d["purchased"].update({"din988-13x19x1": dict(DIN988_13X19)}))
    report = arrangement.analyse(params, _tilt_shim(params, "din988-13x19x1"))
    assert report.failures == ["eyes_tilt: eyes_tilt_bearing_shim (din988-13x19x1, its bore 13) bears on "
                               "eyes_tilt_bearing_right's outer ring, whose face starts at 16.5 (skf-626-2Z): it reaches "
                               "in over the seal or shield; take a shim with a bore of at least 16.5"]
    # the shim is looked through: the DIN 472 ring beyond it locates the outer ring, the bearing is still fixed
    right = _bearing(report, "eyes_tilt_bearing_right")
    assert right.role == "fixed" and right.outer.plus.stop == "eyes_tilt_bearing_ring"
    assert right.outer.plus.through == ("eyes_tilt_bearing_shim",) and right.outer.plus.shim_gap == 0.0
    assert right.shims == [arrangement.ShimFace("eyes_tilt_bearing_shim", "din988-13x19x1", "outer", 13, 19, (16.5, 19),
                                                False)]
    with pytest.raises(arrangement.BearingArrangementError, match="eyes_tilt_bearing_shim .* reaches in over the seal"):
        arrangement.enforce(report)


def test_without_d2_an_outer_rings_face_starts_at_the_pitch_circle(tmp_path):
    """A 626 with no outer_ring_inside: the outer ring's face is taken from the pitch circle (12.5) out; the DIN 988
    13 x 19 passes against it, a shim with a 12 mm bore (clear of the 11 mm inner ring) does not."""
    def edit(d):
        del d["purchased"]["skf-626-2Z"]["outer_ring_inside"]
        d["purchased"]["din988-13x19x1"] = dict(DIN988_13X19)
        d["purchased"]["shim-12x19x1"] = dict(DIN988_13X19, bore=12)
    params = edited(tmp_path, edit)
    report = arrangement.analyse(params, _tilt_shim(params, "din988-13x19x1"))
    assert report.ok, report.failures
    assert _bearing(report, "eyes_tilt_bearing_right").shims == [
        arrangement.ShimFace("eyes_tilt_bearing_shim", "din988-13x19x1", "outer", 13, 19, (12.5, 19), True)]
    assert "    shim eyes_tilt_bearing_shim (din988-13x19x1, 13 x 19) on the outer ring, whose face is 12.5 to 19 " \
           "across: bears on the ring alone" in arrangement.format_report(report).splitlines()
    report = arrangement.analyse(params, _tilt_shim(params, "shim-12x19x1"))
    assert report.failures == ["eyes_tilt: eyes_tilt_bearing_shim (shim-12x19x1, its bore 12) bears on "
                               "eyes_tilt_bearing_right's outer ring, whose face starts at 12.5 (skf-626-2Z): it reaches "
                               "in over the seal or shield; take a shim with a bore of at least 12.5"]


def _at(params, bearing: Part, name: str, shape, z: float, link: str | None = None) -> Part:
    """A stop in the bearing's own frame (its axis z, its faces at 0 and its width), on `link` (its own by default)."""
    link = link or bearing.link
    poses = kinematics.link_poses(params, {})
    to_link = np.linalg.inv(poses[link]) @ poses[bearing.link]
    return Part(name, name, link, "machined", shape, geom.location(to_link) * bearing.placement * loc(z=z),
                material="aluminium-6082")


def _ring(outside, bore, thickness):
    return geom.tube("z", outside, bore, 0, thickness)


def _analyse(params, parts, extra=(), drop=()):
    return arrangement.analyse(params, [p for p in parts if p.name not in drop] + list(extra))


def test_a_61800_clamped_again_fails(params, parts):
    """The old seat: a shoulder inside the outer ring and a DIN 472 ring outside it."""
    b = next(p for p in parts if p.name == "neck_pitch_bearing_right")
    w = params.purchased(b.design).num("width")
    shoulder = _at(params, b, "old_shoulder", _ring(19, 15, 1), -1)
    ring = purchased.retaining_ring(params, "old_ring", "din472-19x1", b.link, b.placement * loc(z=w))
    report = _analyse(params, parts, [shoulder, ring])
    assert not report.ok
    # and the DIN 472's lugs, straight on the outer ring with no shim, reach in over its face onto the seal
    assert report.failures == ["neck_pitch: old_ring (din472-19x1, its lugs in to 10.4 as fitted) bears on "
                               "neck_pitch_bearing_right's outer ring, whose face starts at 14.5 (skf-61800-2RS): it "
                               "reaches onto its shield or seal; put a shim between them",
                               "neck_pitch: neck_pitch_bearing_right locates the shaft one way besides "
                               "neck_pitch_gearhead's output bearings (the fixed bearing): they fight; it must float"]
    with pytest.raises(arrangement.BearingArrangementError, match="neck_pitch: neck_pitch_bearing_right locates"):
        arrangement.enforce(report)


def test_a_floating_ring_without_room_fails(params, parts):
    b = next(p for p in parts if p.name == "neck_roll_bearing_front")
    w = params.purchased(b.design).num("width")
    report = _analyse(params, parts, [_at(params, b, "cover", _ring(19, 15, 1), w + 0.1)])
    [failure] = report.failures
    assert failure.startswith("neck_roll: neck_roll_bearing_front must float, but its outer ring (H7, the sliding one) "
                              "has 0.10 mm of room towards +x to cover: it needs 0.33 mm")


def test_a_tilt_with_both_626_fixed_fails(params, parts):
    """The left 626 held like the right one: its outer ring between two stops in the plate, its inner ring between the
    collar and a clip."""
    b = next(p for p in parts if p.name == "eyes_tilt_bearing_left")
    w = params.purchased(b.design).num("width")
    report = _analyse(params, parts, [_at(params, b, "stop_in", _ring(19, 15, 1), -1), _at(params, b, "stop_out", _ring(19, 15, 1), w),
                                      _at(params, b, "clip", _ring(11, 5, 0.7), w, "eyes_tilt_link")])
    assert _bearing(report, "eyes_tilt_bearing_left").role == "fixed"
    assert report.failures == ["eyes_tilt: 2 fixed bearings (eyes_tilt_bearing_left, eyes_tilt_bearing_right) locate "
                               "the shaft: they fight as it grows; one must float"]


def test_a_tilt_without_a_fixed_bearing_fails(params, parts):
    report = _analyse(params, parts, drop={"eyes_tilt_clip"})
    assert report.failures[0] == ("eyes_tilt: no bearing locates the shaft both ways (no fixed bearing): "
                                  "eyes_tilt_bearing_left is floating, eyes_tilt_bearing_right is one way")


def test_a_gearhead_off_the_shafts_axis_is_no_fixed_bearing(params, parts):
    gear = next(p for p in parts if p.name == "neck_pitch_gearhead")
    moved = Part(gear.name, gear.design, gear.link, gear.kind, gear.local, loc(x=1) * gear.placement, mass=gear.mass)
    report = _analyse(params, parts, [moved], drop={"neck_pitch_gearhead"})
    assert report.failures == ["neck_pitch: the gearhead is listed as the fixed bearing (bearing_arrangement."
                               "gearhead_fixed) but neck_pitch_gearhead's axis is not the shaft's (neck_pitch_bearing_right)"]


def test_a_floating_ring_with_a_tight_fit_fails(tmp_path):
    params = edited(tmp_path, lambda d: d["fits"].update(housing_standing_ring="M7"))
    report = arrangement.analyse(params, _parts(params))
    assert "neck_pitch: neck_pitch_bearing_right floats on its outer ring, but that ring's fit M7 holds it (mean " \
           "interference 6.0 um): a floating ring needs a sliding fit" in report.failures


def test_the_package_reports_the_arrangement(fab):
    data = json.loads((fab / "reports" / "bearing-arrangement.json").read_text())
    assert data["ok"] and data["problems"] == []
    assert {j["joint"]: j["arrangement"] for j in data["joints"]} == {
        "neck_pitch": "gearhead + floating", "neck_roll": "gearhead + floating", "neck_yaw": "cross-located",
        "eyes_tilt": "fixed + floating", "neck_yaw_jackshaft": "fixed + floating",
        "eyes_tilt_jackshaft": "fixed + floating"}
    text = (fab / "reports" / "bearing-arrangement.txt").read_text()
    assert "neck_pitch_bearing_right (skf-61800-2RS): floating" in text
    assert "towards -y 0.00 mm to eyes_tilt_bearing_spacer" in text and "    shim " not in text
