# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The free spans' cables against each other (robogene_head/harness/crossing.py): two loops whose cables meet at a
pose are a crossing, named with the pose and the depth; apart they are not; side by side where both are tied to the
same link they are not counted; the package's spans meet nowhere, and the pitch loop at its old slack (1.0) met the
yaw loop at a corner of the neck's range, which the build now stops on."""
import dataclasses
import json

import numpy as np
import pytest

from robogene_head import kinematics
from robogene_head.harness import clearance, crossing, plan, spec
from robogene_head.harness.plan import Harness, Span

from param_variants import edited


@pytest.fixture(scope="module")
def base(params):
    return spec.load(params)


def _clamp(name, at, direction, link="neck_base", up=(0, 0, 1.0)):
    return spec.Clamp(name, link, np.array(at, float), np.array(direction, float) / np.linalg.norm(direction),
                      np.array(up, float), None)


def _two(base, second_at, second_to, wires=8, links=("neck_base", "neck_base")):
    """Span a -> b along x (an S in the x-y plane, 110 mm of cable) and span c -> d, at rest (no joints)."""
    cls = base.classes["signal-28awg"]
    clamps = {"a": _clamp("a", (0, 0, 0), (1, 0, 0)), "b": _clamp("b", (100, 20, 0), (1, 0, 0)),
              "c": _clamp("c", second_at, (0, 1, 0), links[0]), "d": _clamp("d", second_to, (0, 1, 0), links[1])}
    s = dataclasses.replace(base, clamps=clamps)
    one = Span("a", "b", (), 1, 100.0, 110.0, members=(("w", cls, wires),))
    two = Span("c", "d", (), 1, 100.0, 110.0, members=(("v", cls, wires),))
    return Harness(s, {("a", "b"): one, ("c", "d"): two}, [], [], [])


def test_two_loops_across_each_other_are_a_crossing(params, base):
    h = _two(base, (50, -40, 0), (60, 50, 0))           # c -> d runs up across a -> b in the same plane
    (found,) = crossing.check(params, h)
    assert (found.first, found.second) == (("a", "b"), ("c", "d"))
    od = clearance.bundle_od(h.spans[("a", "b")])
    assert 0 < found.depth_mm <= od + 1e-9 and found.pose == {}
    assert "spans a -> b and c -> d: their cables run" in found.text()


def test_the_same_loops_apart_are_not(params, base):
    od = clearance.bundle_od(_two(base, (0, 0, 0), (0, 0, 0)).spans[("a", "b")])
    assert crossing.check(params, _two(base, (50, -40, 30), (60, 50, 30))) == []      # 30 mm above
    # just over one bundle's diameter apart the bands clear; just under it they touch
    apart = _two(base, (50, -40, od + 0.6), (60, 50, od + 0.6))
    touching = _two(base, (50, -40, od - 0.6), (60, 50, od - 0.6))
    assert crossing.check(params, apart) == [] and len(crossing.check(params, touching)) == 1


def test_cables_tied_side_by_side_to_one_link_are_not_counted(params, base):
    """c starts 3 mm beside b, on the same link: within clamp_zone of both clamps they lie side by side on the part
    they are tied to; on another link the same closeness is a crossing."""
    h = _two(base, (100, 23, 0), (180, 80, 0))
    assert crossing.check(params, h) == []
    head = kinematics.link_poses(params, {})["head_frame"]
    assert np.allclose(head[:3, :3], np.eye(3))      # at rest the head's frame is the base's, moved
    other = _two(base, tuple(np.array((100, 23, 0)) - head[:3, 3]), tuple(np.array((180, 80, 0)) - head[:3, 3]),
                 links=("head_frame", "head_frame"))
    assert [(x.first, x.second) for x in crossing.check(params, other)] == [(("a", "b"), ("c", "d"))]


def test_a_crossing_stops_the_build_with_the_pose(params, base):
    h = _two(base, (50, -40, 0), (60, 50, 0))
    c = clearance.Clearance(10, [], [], crossings=crossing.check(params, h))
    assert not c.ok and c.problems[0].startswith("spans a -> b and c -> d: their cables run")


def test_the_packages_spans_meet_nowhere(fab):
    cl = json.loads((fab / "harness" / "harness.json").read_text())["span_clearance"]
    assert cl["crossings"] == [] and cl["ok"] is True
    assert "Cables against cables" in (fab / "reports" / "harness.txt").read_text()


def test_the_pitch_loop_at_its_old_slack_meets_the_yaw_loop(params, assembly, tmp_path):
    """The broken variant: with a slack of 1.0 the pitch loop (roll_exit -> roll_feed) hangs far enough that at the
    corner of the neck's range the yaw loop (yaw_cross -> head_entry) rests on it."""
    def edit(data):
        data["harness"]["clamps"]["roll_exit"]["slack"] = 1.0
    old = edited(tmp_path, edit)
    h = plan.plan(old, spec.load(old), assembly.parts)
    found = {(x.first, x.second): x for x in crossing.check(old, h)}
    pair = (("roll_exit", "roll_feed"), ("yaw_cross", "head_entry"))
    assert list(found) == [pair]
    assert found[pair].depth_mm > 0.5 and found[pair].pose["neck_yaw"] == 45.0
