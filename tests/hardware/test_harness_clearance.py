# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The spans' clearance of the parts: a part across a span's curve blocks it, and is named; moved aside it does not;
the clamp's own link may touch the cables within clamp_zone of the clamp, any other part may not; the bundle's
diameter grows with its wires; flat cables are checked as bands; a clamp must lie on or near a part of its own link,
not inside one; the package reports it for every span and every clamp; the build stops on a blocked span but those
harness.unresolved names, and on a named one that is clear."""
import dataclasses
import json

import cadquery as cq
import numpy as np
import pytest

from robogene_head import kinematics
from robogene_head.harness import clearance, plan, spec
from robogene_head.harness.plan import Harness, Span
from robogene_head.parts.base import Part, loc
from robogene_head_model.params import ParameterError

from param_variants import edited


def _box(name, link, at, size=(6, 6, 6)):
    return Part(name, name, link, "machined", cq.Workplane().box(*size).val(), loc(*at))


@pytest.fixture(scope="module")
def base(params):
    return spec.load(params)


def _harness(base, members, a_at=(0, 0, 0), b_at=(100, 20, 0), links=("neck_base", "neck_base"), up=(0, 0, 1.0)):
    """One span at rest (no joints) from clamp a to clamp b, both clamps along +x (an S in the x-y plane), 110 mm
    long."""
    a = spec.Clamp("a", links[0], np.array(a_at, float), np.array([1.0, 0, 0]), np.array(up, float))
    b = spec.Clamp("b", links[1], np.array(b_at, float), np.array([1.0, 0, 0]), np.array(up, float))
    s = dataclasses.replace(base, clamps={"a": a, "b": b})
    span = Span("a", "b", (), 1, 100.0, 110.0, members=tuple(members))
    return Harness(s, {("a", "b"): span}, [], [], [])


def _clear(c):
    """Every span clear of the parts (the clamps' support is its own test below)."""
    return all(s.ok for s in c.spans)


def _round(base, wires=8):
    return [("wires", base.classes["signal-28awg"], wires)]


def _middle(params, h):
    """The span's curve at its middle sample, at rest, in the world (the neck base's frame): point, width direction."""
    a, b = h.spec.clamps["a"], h.spec.clamps["b"]
    poses = kinematics.link_poses(params, {})
    c = clearance.spans.curve(plan.frame(poses[a.link], a), plan.frame(poses[b.link], b), 110.0)
    middle = len(c.directions) // 2
    return c.points[middle], c.widths[middle]


def test_a_part_across_the_span_blocks_it_and_is_named(params, base):
    h = _harness(base, _round(base))
    mid, _ = _middle(params, h)
    c = clearance.check(params, h, [_box("elsewhere", "head_frame", (0, 0, 0)), _box("across", "neck_base", mid)])
    assert not _clear(c)
    (s,) = c.spans
    assert [b.part for b in s.blocked] == ["across"]
    assert 40 < s.blocked[0].at_mm < 60
    spans = [p for p in c.problems if p.startswith("span")]
    assert "span a -> b: the round wires" in spans[0] and "across (neck_base)" in spans[0]


def test_a_part_beside_the_span_does_not(params, base):
    h = _harness(base, _round(base))
    od = clearance.bundle_od(h.spans[("a", "b")])
    mid, _ = _middle(params, h)
    up = np.array([0, 0, 1.0])     # the S lies in the x-y plane: a box above it, its face od/2 + 0.3 above the centre line
    assert _clear(clearance.check(params, h, [_box("above", "neck_base", mid + up * (3 + od / 2 + 0.3))]))
    # ...and just into the bundle's surface it blocks: the cross-section counts, not only the centre line.
    assert not _clear(clearance.check(params, h, [_box("grazing", "neck_base", mid + up * (3 + od / 2 - 0.3))]))


def test_the_clamps_own_link_may_touch_near_the_clamp(params, base):
    zone = params.root.node("harness").num("clamp_zone")
    assert zone > 4
    head = kinematics.link_poses(params, {})["head_frame"]
    assert np.allclose(head[:3, :3], np.eye(3))    # at rest the head's frame is the base's, moved

    def in_head(p):
        return tuple(np.array(p, float) - head[:3, 3])
    h = _harness(base, _round(base), b_at=in_head((100, 20, 0)), links=("neck_base", "head_frame"))
    near_a = (2.5, 0, 0)          # within the zone of clamp a, which is on neck_base
    assert _clear(clearance.check(params, h, [_box("plate", "neck_base", near_a, (2, 20, 20))]))
    c = clearance.check(params, h, [_box("other_link", "head_frame", in_head(near_a), (2, 20, 20))])
    assert [b.part for b in c.spans[0].blocked] == ["other_link"]
    far, _ = _middle(params, h)           # the clamp's own link, away from the clamp, blocks
    assert not _clear(clearance.check(params, h, [_box("plate", "neck_base", far, (2, 20, 20))]))


def test_the_bundle_grows_with_its_wires(base):
    cls = base.classes["signal-28awg"]
    one = clearance.bundle_od(Span("a", "b", (), 1, 1, 1, members=(("w", cls, 1),)))
    many = clearance.bundle_od(Span("a", "b", (), 1, 1, 1, members=(("w", cls, 4), ("v", cls, 12))))
    assert many == pytest.approx(one * 4, rel=1e-9)      # 16 wires: 4 x the diameter of one at the same packing
    assert one == pytest.approx(cls.wire_od / clearance.PACKING ** 0.5)


def test_a_flat_cable_is_checked_across_its_width(params, base):
    flat = base.camera_class
    assert flat.width > 10
    h = _harness(base, [("camera", flat, 1)], up=(0, 1.0, 0))
    mid, width = _middle(params, h)
    # The clamps' face normal is y, in the S's plane, so the band stands on edge, its width along z: a post at the
    # band's edge, far from its centre line (which stays in z = 0), is met; beyond the edge it is not.
    assert abs(width[2]) > 1 - 1e-9
    edge = flat.width / 2
    assert not _clear(clearance.check(params, h, [_box("post", "neck_base", mid + width * (edge - 1.5), (2, 2, 2))]))
    assert _clear(clearance.check(params, h, [_box("post", "neck_base", mid + width * (edge + 1.5), (2, 2, 2))]))


def test_the_package_reports_every_spans_clearance(fab, params):
    data = json.loads((fab / "harness" / "harness.json").read_text())
    cl = data["span_clearance"]
    assert cl["enforced"] is True and cl["ok"] is True and cl["problems"] == []
    assert {(s["from"], s["to"]) for s in cl["spans"]} == {(s["from"], s["to"]) for s in data["spans"]}
    assert all(s["poses"] >= 1 for s in cl["spans"])
    assert {k["name"] for k in cl["clamps"]} == set(params.root.node("harness").raw("clamps"))
    assert "Span clearance" in (fab / "reports" / "harness.txt").read_text()


def test_every_span_is_clear_of_the_parts(fab):
    """The routes were laid out with this check (docs/fabricate.md, "Wire the head"): in the package every free
    span is clear over its joints' range and every clamp held, and harness.unresolved names none. The neck crosses
    pitch, roll and yaw in a loop each; the camera cables cross each pan and the tilt in loops of their own, joined on
    the cable shelf."""
    cl = json.loads((fab / "harness" / "harness.json").read_text())["span_clearance"]
    spans = {(s["from"], s["to"]): s for s in cl["spans"]}
    assert cl["unresolved"] == [] and cl["known"] == []
    assert set(spans) == {("roll_exit", "roll_feed"), ("roll_cross", "roll_land"), ("yaw_cross", "head_entry"),
                          ("tilt_feed_l", "tilt_arm_l"), ("tilt_feed_r", "tilt_arm_r"), ("eye_l", "pan_feed_l"),
                          ("eye_r", "pan_feed_r"), ("cam_arm_l", "cam_feed_l"), ("cam_arm_r", "cam_feed_r")}
    # 7 samples of its own joint, and 3 of each joint near it: the neck's loops over the other two neck joints, the
    # loops across tilt (the drives' and the cameras') with both eyes panned, the loops across a pan with the eyes tilted
    across_pan = {("eye_l", "pan_feed_l"), ("eye_r", "pan_feed_r")}      # one joint near them: the tilt
    for key, span in spans.items():
        assert span["blocked"] == [] and span["poses"] == 7 * 3 ** (1 if key in across_pan else 2), key
    assert all(k["ok"] for k in cl["clamps"])


def _blocked_over(params, span, a, b, models, near):
    """The links whose parts the span's cables touch with the joints `near` (name: angles) swept with its own."""
    zone = params.root.node("harness").num("clamp_zone")
    return {x.link for x in clearance.span_clearance(params, span, a, b, models, zone, 7, near).blocked}


def test_the_sweep_takes_in_the_joints_near_a_span(params):
    """harness.near_joints, at harness.near_samples angles over each range, less the joints the span crosses."""
    near = clearance.near_joints(params, ("neck_roll",))
    assert sorted(near) == ["neck_pitch", "neck_yaw"]
    yaw = params.joints["neck_yaw"]
    assert list(near["neck_yaw"]) == [yaw.lower, (yaw.lower + yaw.upper) / 2, yaw.upper]
    assert sorted(clearance.near_joints(params, ("neck_pitch", "neck_roll"))) == ["neck_yaw"]
    assert sorted(clearance.near_joints(params, ("left_eye_pan",))) == ["eyes_tilt"]
    assert clearance.near_joints(params, ()) == {}


@pytest.mark.parametrize("edit, message", [
    (lambda h: h["near_joints"].update(neck_roll=["neck_pitch", "neck_twist"]),
     r"harness\.near_joints\.neck_roll: 'neck_twist' is no joint of the head"),
    (lambda h: h["near_joints"].update(neck_roll="neck_pitch"), r"harness\.near_joints\.neck_roll: expected a list"),
    (lambda h: h["near_joints"].update(neck_twist=["neck_pitch"]), r"harness\.near_joints\.neck_twist: is no joint"),
    (lambda h: h.update(near_samples=2.5), r"harness\.near_samples: expected a whole number"),
])
def test_bad_near_joints_are_named(params, tmp_path, edit, message):
    def apply(data):
        edit(data["harness"])
    with pytest.raises(ParameterError, match=message):
        clearance.near_joints(edited(tmp_path, apply), ("neck_roll",))


def test_the_sweep_over_the_joints_near_a_span_finds_what_its_own_misses(params, base, assembly):
    """The broken variant: the first roll loop the clamp search found is clear over roll alone, but meets the head
    frame with the head yawed to -45 deg, one of the yaw angles the build's sweep over the joints near the loop
    takes."""
    first = dict(base.clamps)
    first["roll_cross"] = spec.Clamp("roll_cross", "neck_pitch_link", np.array([-29.0, 10, 47]),
                                     np.array([0, 0.978, -0.208]) / np.linalg.norm([0, 0.978, -0.208]),
                                     np.array([1.0, 0, 0]), None)
    first["roll_land"] = spec.Clamp("roll_land", "neck_roll_link", np.array([15.0, 19, 13]),
                                    np.array([0.592, -0.718, 0.366]) / np.linalg.norm([0.592, -0.718, 0.366]),
                                    np.array([-0.806, -0.551, 0.215]), None)
    s2 = dataclasses.replace(base, clamps=first)
    users = [m for m in plan.plan(params, base, assembly.parts).spans[("roll_cross", "roll_land")].members]
    span = plan.check_span(params, s2, first["roll_cross"], first["roll_land"], users)
    models = clearance._Models(assembly.parts)
    assert _blocked_over(params, span, first["roll_cross"], first["roll_land"], models, {"neck_yaw": [0.0]}) == set()
    assert "head_frame" in _blocked_over(params, span, first["roll_cross"], first["roll_land"], models,
                                         {"neck_yaw": [-45.0]})
    assert -45.0 in clearance.near_joints(params, span.joints)["neck_yaw"]


def test_the_eyes_camera_loops_keep_to_their_own_sides(params, base):
    """The build checks each span against the parts, not against other cables: the two camera cables' loops about the
    pan axes, which both end on the cable shelf between the eyes, are laid so that each stays on its own eye's side
    of the middle over its whole pan range, with room for the cables' thickness, so they never meet whatever the
    vergence."""
    for side, sign in (("l", 1), ("r", -1)):
        a, b = base.clamps[f"eye_{side}"], base.clamps[f"pan_feed_{side}"]
        span = plan.check_span(params, base, a, b, [("camera", base.classes["camera-ffc"], 1)])
        assert span.joints == (f"{'left' if side == 'l' else 'right'}_eye_pan",) and len(span.curves) == 7
        nearest = min(float(np.min(sign * c.points[:, 1])) for c in span.curves)
        assert nearest > 1.0, (side, nearest)


def _named(params, tmp_path, entries, h):
    def edit(data):
        data["harness"]["unresolved"] = entries
    return clearance.unresolved(edited(tmp_path, edit), h)


def test_a_blocked_span_stops_the_build_unless_named_and_a_named_clear_one_does_too(params, base, tmp_path):
    """A span through a part is a problem (the build stops on it); named in harness.unresolved it is reported as
    known instead; a named span that is clear is a problem again, so the list cannot outlive what it names."""
    h = _harness(base, _round(base))
    mid, _ = _middle(params, h)
    holders = [_box("holds_a", "neck_base", (0, 0, -4), (4, 4, 4)),
               _box("holds_b", "neck_base", (100, 20, -4), (4, 4, 4))]
    blocking = holders + [_box("across", "neck_base", mid)]
    bare = clearance.check(params, h, blocking)
    assert not bare.ok and any("pass through across" in p for p in bare.problems)
    (tmp_path / "named").mkdir()
    why = _named(params, tmp_path / "named", [{"from": "a", "to": "b", "why": "being redesigned"}], h)
    assert why == {("a", "b"): "being redesigned"}
    named = clearance.check(params, h, blocking, why)
    assert named.ok and named.problems == [] and any("across" in line for line in named.known)
    assert not any(s.ok for s in named.spans)
    stale = clearance.check(params, h, holders + [_box("aside", "neck_base", mid + np.array([0, 0, 40.0]))], why)
    assert not stale.ok and stale.problems == ["span a -> b: clear of every part, but harness.unresolved still names "
                                               "it: take it off that list"]


@pytest.mark.parametrize("entries, message", [
    ([{"from": "a", "to": "c", "why": "x"}], r"harness\.unresolved\[0\]: a -> c is no free span of the harness"),
    ([{"from": "a", "to": "b", "why": "x"}, {"from": "a", "to": "b", "why": "y"}],
     r"harness\.unresolved\[1\]: a -> b is named twice"),
    ([{"from": "a", "to": "b"}], r"harness\.unresolved\[0\]\.why: missing"),
    ({"from": "a", "to": "b", "why": "x"}, r"harness\.unresolved: expected a list"),
])
def test_bad_unresolved_entries_are_named(params, base, tmp_path, entries, message):
    with pytest.raises(ParameterError, match=message):
        _named(params, tmp_path, entries, _harness(base, _round(base)))


def test_a_clamp_must_be_held_by_a_part_of_its_link(params, base):
    standoff = params.root.node("harness").num("clamp_standoff")
    h = _harness(base, _round(base))
    # a plate under both clamps, its top face 1 mm below them: both are held
    plate = _box("plate", "neck_base", (50, 10, -1.5), (120, 40, 1))
    held = {k.name: k for k in clearance.check(params, h, [plate]).clamps}
    assert held["a"].ok and held["b"].ok and held["a"].nearest == "plate"
    assert held["a"].distance == pytest.approx(1.0, abs=0.05)
    # the plate further down than clamp_standoff: nothing holds them
    low = _box("plate", "neck_base", (50, 10, -standoff - 1.5), (120, 40, 1))
    c = clearance.check(params, h, [low])
    assert not c.ok and not c.clamps[0].ok
    assert any(p.startswith("clamp a:") and "nothing holds it" in p for p in c.problems)
    # a part of another link next to the clamp does not hold it
    other = _box("other", "head_frame", (0, 0, -118), (6, 6, 1))
    assert not {k.name: k for k in clearance.check(params, h, [low, other]).clamps}["a"].ok


def test_a_part_turning_in_the_clamps_link_does_not_hold_it(params, base, assembly):
    """A pulley or coupling on a jackshaft turns in its link: a tie on it would wind the cables up. The standing part
    further off is the one measured; if it is beyond clamp_standoff the clamp is not held."""
    standoff = params.root.node("harness").num("clamp_standoff")
    h = _harness(base, _round(base))
    pulley = _box("pulley", "neck_base", (0, 0, -1.5), (6, 6, 1))
    frame = _box("frame", "neck_base", (0, 0, -standoff - 1.5), (6, 6, 1))
    models = clearance._Models([pulley, frame])
    held = {k.name: k for k in clearance.clamp_supports(h, models, standoff)}
    assert held["a"].ok and held["a"].nearest == "pulley"
    turning = {k.name: k for k in clearance.clamp_supports(h, models, standoff, frozenset({"pulley"}))}
    assert not turning["a"].ok and turning["a"].nearest == "frame"
    alone = clearance._Models([pulley])
    (lonely, _) = clearance.clamp_supports(h, alone, standoff, frozenset({"pulley"}))
    problems = clearance.Clearance(10, [], [lonely]).problems
    assert problems == ["clamp a: no part of neck_base stands in the link to hold it"]
    # in the head: the jackshafts and what turns on them
    turns = clearance.turning_parts(params, assembly.parts)
    assert {"eyes_tilt_jackshaft", "eyes_tilt_coupling", "eyes_tilt_motor_pulley", "neck_yaw_coupling"} <= turns
    assert "eyes_tilt_jackshaft_housing" not in turns and "head_floor" not in turns


def test_a_clamp_inside_a_part_is_refused_and_one_on_its_face_is_not(params, base):
    h = _harness(base, _round(base))
    around = _box("block", "neck_base", (0, 0, 0), (8, 8, 8))          # clamp a at its centre
    c = clearance.check(params, h, [around])
    assert {k.name: k for k in c.clamps}["a"].inside == "block"
    assert any("clamp a: inside block (neck_base)" in p for p in c.problems)
    on_face = _box("block", "neck_base", (0, 0, -4), (8, 8, 8))        # its top face through clamp a
    assert {k.name: k for k in clearance.check(params, h, [on_face]).clamps}["a"].ok


def test_the_check_leaves_the_parts_unmeshed(params, base):
    """It meshes copies: a mesh left on a part's faces changes what BoundingBox() gives every later step of the
    build, which would then depend on whether the harness step ran or was cached."""
    ball = Part("ball", "ball", "neck_base", "machined", cq.Workplane().sphere(7).val(), loc(50, 30, 0))
    before = ball.shape.BoundingBox()
    clearance.check(params, _harness(base, _round(base)), [ball])
    after = ball.shape.BoundingBox()
    assert (after.xmin, after.xmax, after.zmax) == (before.xmin, before.xmax, before.zmax)
