# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The eye tilt on a fixed and a floating bearing: the right one held both ways in the right plate's boss (shoulder,
spacer ring and DIN 472 ring) and on the journal (collar and DIN 6799 clip), the left one against its journal's collar
with its outer ring free to slide in the left plate's through-bore; the seat refuses what would rub or has no room, and
a spacer ring that could reach the shield or not go into the seat."""
import pytest

from robogene_head import bearing_arrangement as arrangement
from robogene_head import bearing_loads, geom, kinematics, massprops
from robogene_head.parts.base import Part
from robogene_head.geom import distance, location
from robogene_head.parts import eyes, head_frame, joint_encoders, neck, tilt_bearings
from robogene_head_model.params import ParameterError

from param_variants import edited


@pytest.fixture(scope="module")
def world(params):
    poses = kinematics.link_poses(params, {})
    parts = head_frame.build(params) + eyes.build(params) + joint_encoders.build(params)
    return {p.name: p.shape.moved(location(poses[p.link])) for p in parts
            if p.name.startswith(("eyes_tilt_", "head_side_plate_"))}


def test_the_fixed_bearing_is_held_both_ways(params, world):
    bearing, plate, frame = world["eyes_tilt_bearing_right"], world["head_side_plate_right"], world["eyes_tilt_frame"]
    ring, spacer, clip = world["eyes_tilt_bearing_ring"], world["eyes_tilt_bearing_spacer"], world["eyes_tilt_clip"]
    # outer ring: against the plate's shoulder inside, the spacer ring and the DIN 472 ring outside
    assert distance(bearing, plate) < 1e-6 and bearing.intersect(plate).Volume() < 1e-3
    inside, outside, thickness = tilt_bearings.layout(params).spacer
    assert distance(ring, bearing) == pytest.approx(thickness)
    assert distance(spacer, bearing) < 1e-6 and distance(ring, spacer) < 1e-6
    assert ring.intersect(plate).Volume() < 1e-3
    # the spacer bears on the outer ring's face alone (D2 16.5 out), inside the seat, clear of the plate's bore
    assert params.purchased("skf-626-2Z").num("outer_ring_inside") == 16.5 < inside < outside < 19
    assert spacer.BoundingBox().xlen == pytest.approx(outside)
    assert spacer.intersect(plate).Volume() < 1e-3 and distance(spacer, plate) > 0
    # inner ring: against the journal's collar inside, the clip outside, the clip in its groove
    assert distance(bearing, frame) < 1e-6 and bearing.intersect(frame).Volume() < 1e-3
    assert distance(clip, bearing) < 1e-6 and clip.intersect(frame).Volume() < 1e-3
    lay = tilt_bearings.layout(params)
    bb = bearing.BoundingBox()
    assert bb.ymax == pytest.approx(lay.bearing)
    assert frame.BoundingBox().ymin == pytest.approx(lay.shaft_end)


def test_the_ring_lugs_stand_off_the_turning_inner_ring_and_clip(params, world):
    """The DIN 472 ring's lugs (not modelled) reach in to lug_inner_diameter: a tube of that bore at the ring must
    clear the clip and the journal, which turn."""
    ring = params.purchased(neck.bearing_ring(params))
    bb = world["eyes_tilt_bearing_ring"].BoundingBox()
    tx, _, tz = params.joints["eyes_tilt"].origin
    lugs = geom.tube("y", ring.num("groove_diameter"), ring.num("lug_inner_diameter"), bb.ymin, bb.ymax,
                     (tx, tz))
    assert distance(lugs, world["eyes_tilt_clip"]) >= neck.LUG_GAP - 1e-6
    assert distance(lugs, world["eyes_tilt_frame"]) > 0


def test_the_floating_bearing_sits_on_its_collar_and_slides_in_its_bore(params, world):
    bearing, plate, frame = world["eyes_tilt_bearing_left"], world["head_side_plate_left"], world["eyes_tilt_frame"]
    assert distance(bearing, frame) < 1e-6 and bearing.intersect(frame).Volume() < 1e-3
    # no shoulder either side: the plate has no material inside the outer ring's diameter near the bearing
    tx, _, tz = params.joints["eyes_tilt"].origin
    bb = bearing.BoundingBox()
    outside = params.purchased(params.drive("eyes_tilt").text("bearing")).num("outside")
    for y0, y1 in ((bb.ymin - 0.5, bb.ymin), (bb.ymax, bb.ymax + 0.5)):
        probe = geom.tube("y", outside - 0.1, outside - 4, y0, y1, (tx, tz))
        assert probe.intersect(plate).Volume() < 1e-6
    # the collar touches the inner ring only: it is within the inner ring's face
    inner_ring = params.purchased(params.drive("eyes_tilt").text("bearing")).num("inner_ring_outside")
    assert params.geometry("tilt_bearings").num("collar") <= inner_ring


def test_the_journal_carries_the_magnet_holder_beyond_the_clip_and_the_boss(params, world):
    """The right journal stands the holder's protrusion out of the boss's face; the holder on it stands off the
    boss and the ring by the fabricator's minimum and clear of the clip inside the boss; the encoder's bracket stands
    on the plate's outer face beside the boss."""
    lay = tilt_bearings.layout(params)
    end = world["eyes_tilt_frame"].BoundingBox().ymin
    assert end == pytest.approx(-lay.outer - joint_encoders.shaft_protrusion(params))
    holder, plate = world["eyes_tilt_magnet_holder"], world["head_side_plate_right"]
    minimum = params.geometry("clearances").num("minimum")
    assert distance(holder, plate) >= minimum - 1e-6
    assert distance(holder, world["eyes_tilt_bearing_ring"]) >= minimum - 1e-6
    assert distance(holder, world["eyes_tilt_clip"]) > 0
    assert holder.BoundingBox().ymax < -lay.outer                  # wholly outside the boss
    bracket = world["eyes_tilt_encoder_bracket"]
    hw = params.geometry("head", "floor").num("half_width")
    assert bracket.BoundingBox().ymax == pytest.approx(-hw)        # on the plate's outer face
    boss = tilt_bearings.right_boss(params).moved(location(kinematics.link_poses(params, {})["head_frame"]))
    assert distance(bracket, boss) >= minimum - 1e-6


# DIN 6799 size 5, the tilt's clip before: groove 5, s 0.7, up to 11.3 across as fitted (the DIN 6799 table as
# transcribed in the FreeCAD Fasteners workbench's din6799def.csv)
SIZE_5 = {"kind": "shaft_ring", "shaft": 6, "groove_diameter": 5, "groove_width": 0.74, "thickness": 0.7,
          "groove_edge": 1.2, "outside_diameter": 11.3, "lug_outer_diameter": 11.3, "mass": 0.0002}


def _size_5_clip(data):
    data["purchased"]["din6799-5"] = dict(SIZE_5)
    data["geometry"]["tilt_bearings"]["clip"] = "din6799-5"


def _wide_clip_thin_spacer(data):
    data["purchased"]["din6799-4"].update(outside_diameter=10.5, lug_outer_diameter=10.5)
    data["geometry"]["tilt_bearings"]["spacer"]["thickness"] = 0.5


def _spacer(**kw):
    return lambda data: data["geometry"]["tilt_bearings"]["spacer"].update(kw)


@pytest.mark.parametrize("edit, message", [
    (_size_5_clip, r"geometry\.tilt_bearings\.clip: din6799-5 \(11\.3 across\) reaches beyond the skf-626-2Z's inner ring"),
    (_wide_clip_thin_spacer,
     r"geometry\.tilt_bearings\.spacer\.thickness: 0\.5 leaves the din472-19x1 ring's lugs"),
    # a DIN 988 13 x 19's bore: over the shield at once
    (_spacer(inside=13), r"geometry\.tilt_bearings\.spacer\.inside: 13 reaches in to 12\.379 \(ISO 2768-m, and shifted "
                         r"by its 0\.421 mm of play in the 19 H7 seat\), over the skf-626-2Z's shield: its bore must "
                         r"stay outside the outer ring's face, which starts at 16\.5"),
    # 16.8 clears D2 as drawn, not at its smallest (16.6) pushed 0.421 to one side
    (_spacer(inside=16.8), r"spacer\.inside: 16\.8 reaches in to 16\.179 .*0\.421 mm of play"),
    # 19 across goes into the 19 mm seat as drawn, not at its largest (19.2)
    (_spacer(outside=19), r"geometry\.tilt_bearings\.spacer\.outside: 19 \(up to 19\.2 to ISO 2768-m\) must go into the "
                          r"19 mm seat"),
    (_spacer(inside=17.2, outside=17.3), r"spacer\.outside: 17\.3 .* stay over the 17\.2 mm bore"),
    (_spacer(thickness=0.2), r"din472-19x1 ring's lugs reach in to 10\.4, over the eyes_tilt bearing's inner ring \(11 "
                             r"across\).*a spacer ring at least 0\.3 thick.*this one: 0\.2"),
    (lambda d: d["geometry"]["tilt_bearings"].update(collar=12), r"geometry\.tilt_bearings\.collar: 12 must be"),
    (lambda d: d["geometry"]["tilt_bearings"]["boss"].update(thickness=3),
     r"the wall holding the eyes_tilt bearing is 9 thick"),
])
def test_a_tilt_seat_that_cannot_hold_its_bearing_is_refused(tmp_path, edit, message):
    with pytest.raises(ParameterError, match=message):
        tilt_bearings.layout(edited(tmp_path, edit))


@pytest.mark.timeout(900)
def test_the_tilt_bearings_carry_the_eyes(params, assembly):
    props = massprops.link_props(params, assembly.parts)
    report = bearing_loads.analyse(params, assembly.parts, props)
    tilt = [b for b in report.loads if b.joint == "eyes_tilt"]
    assert sorted(b.bearing for b in tilt) == ["eyes_tilt_bearing_left", "eyes_tilt_bearing_right"]
    assert all(b.safety >= report.required for b in tilt) and report.ok


def test_the_clip_stays_within_the_inner_rings_face(params):
    """The DIN 6799 size 4 on the 6 mm journal: 9.3 across as fitted (d3 max) against the 626's 11 mm face (da max)."""
    parts = head_frame.build(params) + eyes.build(params)
    report = arrangement.analyse(params, parts)
    right = next(b for j in report.joints for b in j.bearings if b.bearing == "eyes_tilt_bearing_right")
    assert right.inner.plus.stop == "eyes_tilt_clip" or right.inner.minus.stop == "eyes_tilt_clip"
    assert arrangement.ring_faces(params, right, {p.name: p for p in parts}, report.located_within) == []
    clip = params.purchased(params.geometry("tilt_bearings").text("clip"))
    assert clip.num("lug_outer_diameter") == 9.3 <= params.purchased("skf-626-2Z").num("inner_ring_outside")


def test_a_size_5_clip_straight_on_the_626_fails_the_arrangement_check(params, tmp_path):
    """The old design's washer where the clip is: 11.3 across as fitted, over the 626's 11 mm inner ring face onto the
    shield; the measured check names it (the seat's own rule refuses it too, above)."""
    old = edited(tmp_path, lambda data: data["purchased"].update({"din6799-5": dict(SIZE_5)}))
    parts = [Part(p.name, "din6799-5", p.link, p.kind, p.local, p.placement, mass=p.mass) if p.name == "eyes_tilt_clip"
             else p for p in head_frame.build(old) + eyes.build(old)]
    report = arrangement.analyse(old, parts)
    assert report.failures == ["eyes_tilt: eyes_tilt_clip (din6799-5, 11.3 across as fitted) bears on "
                               "eyes_tilt_bearing_right's inner ring, whose face is 11 across (skf-626-2Z): it reaches "
                               "onto its shield or seal; put a spacer between them or take a smaller ring"]
    with pytest.raises(arrangement.BearingArrangementError, match="eyes_tilt_clip \\(din6799-5, 11.3 across"):
        arrangement.enforce(report)
