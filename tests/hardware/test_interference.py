# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""No interference between parts over the joint sweep; every moving pair keeps the minimum clearance.

The full sweep (every joint over its range plus every corner of the neck and tilt ranges) runs in `make fab`;
its report is checked here, and a sweep of each joint's end stops is recomputed. The checker itself is shown
to catch an overlap and an undeclared contact."""
import json

import numpy as np
import pytest
from OCP.BRepMesh import BRepMesh_IncrementalMesh

from robogene_head import geom, kinematics
from robogene_head.assembly import Assembly
from robogene_head.checks import interference
from robogene_head.parts import Part
from robogene_head.parts.base import loc


def test_package_report_has_no_interference(fab, params):
    report = json.loads((fab / "reports" / "interference.json").read_text())
    assert report["ok"]
    assert report["interferences"] == [] and report["undeclared_contacts"] == [] and report["low_clearances"] == []
    assert report["poses"] == len(interference.sweep_poses(params))
    minimum = params.geometry("clearances").num("minimum")
    assert all(r["distance_mm"] >= minimum for r in report["closest_approach"])
    assert (fab / "reports" / "interference.txt").read_text().startswith("interference check:")


# Thirteen poses of the whole assembly's check, in this process (the build's sweep is cached): about a minute on an
# idle 2-core machine, over two when it is shared.
@pytest.mark.timeout(600)
def test_end_stops_of_every_joint(params, assembly):
    poses = [{}]
    for name, (lo, hi) in params.control_limits.items():
        poses += [{name: lo}, {name: hi}]
    report = interference.check(params, assembly, poses)
    assert report.ok, interference.format_report(report, report.minimum)


def _by_name(assembly, *names):
    return [p for p in assembly.parts if p.name in names]


def test_an_overlap_is_caught(params, assembly):
    intruder = Part("intruder", "intruder", "head_frame", "machined", geom.box(-5, 5, -5, 5, -40, -20), loc(),
                    material="aluminium-6082")
    small = Assembly(params, _by_name(assembly, "neck_roll_stage") + [intruder])
    report = interference.check(params, small, [{}])
    assert [(r.a, r.b) for r in report.interferences] == [("neck_roll_stage", "intruder")]
    assert report.interferences[0].overlap > 100
    assert not report.ok


def test_a_moving_contact_that_is_not_a_fit_is_caught(params, assembly):
    # A block on the head resting on the roll stage's top face, beside the yaw shaft: it rubs when the yaw turns.
    top = params.geometry("neck_roll_stage", "body").num("height") / 2 - params.joints["neck_yaw"].origin[2]
    toucher = Part("toucher", "toucher", "head_frame", "machined", geom.box(10, 14, 10, 14, top, top + 4), loc(),
                   material="aluminium-6082")
    small = Assembly(params, _by_name(assembly, "neck_roll_stage") + [toucher])
    report = interference.check(params, small, [{"neck_yaw": 10}])
    assert report.interferences == []
    assert [(r.a, r.b) for r in report.undeclared_contacts] == [("neck_roll_stage", "toucher")]


def test_a_tight_gap_is_reported_low(params, assembly):
    top = params.geometry("neck_roll_stage", "body").num("height") / 2 - params.joints["neck_yaw"].origin[2]
    close = Part("close", "close", "head_frame", "machined", geom.box(10, 14, 10, 14, top + 0.3, top + 4), loc(),
                 material="aluminium-6082")
    report = interference.check(params, Assembly(params, _by_name(assembly, "neck_roll_stage") + [close]), [{}])
    assert [(r.a, r.b) for r in report.low] == [("neck_roll_stage", "close")]
    assert report.low[0].distance == pytest.approx(0.3, abs=1e-6)


def test_the_check_leaves_the_parts_unmeshed(params):
    """It meshes copies: a mesh left on a part's faces changes what BoundingBox() gives every later step of the
    build, which would then depend on whether the interference step ran or was cached."""
    ball = Part("ball", "ball", "head_frame", "machined", geom.sphere(7), loc(0, 0, 60), material="aluminium-6082")
    peg = Part("peg", "peg", "neck_base", "machined", geom.cyl("z", 10, 0, 10), loc(), material="aluminium-6082")
    before = [p.shape.BoundingBox() for p in (ball, peg)]
    interference.check(params, Assembly(params, [ball, peg]), [{}])
    after = [p.shape.BoundingBox() for p in (ball, peg)]
    assert [(b.xmin, b.xmax, b.zmin, b.zmax) for b in after] == [(b.xmin, b.xmax, b.zmin, b.zmax) for b in before]


def test_a_mesh_left_on_the_parts_does_not_change_the_result(params):
    """A part meshed earlier in the build (its STL, the assembly's GLB) is measured as one never meshed: the check
    meshes copies at its own deflection. Two balls on two links 3 mm apart: a mesh distance, reported as such."""
    poses = kinematics.link_poses(params, {})
    a_world = poses["head_frame"] @ [0, 0, 60, 1]
    b_local = np.linalg.inv(poses["neck_base"]) @ (a_world + [17, 0, 0, 0])     # radii 7 + 7 and a 3 mm gap

    def run(premeshed):
        a = Part("a", "a", "head_frame", "machined", geom.sphere(7), loc(0, 0, 60), material="aluminium-6082")
        b = Part("b", "b", "neck_base", "machined", geom.sphere(7), loc(*b_local[:3]), material="aluminium-6082")
        for p in (a, b) if premeshed else ():
            BRepMesh_IncrementalMesh(p.local.wrapped, 0.01, False, 0.1, True).Perform()
        report = interference.check(params, Assembly(params, [a, b]), [{}])
        return [(r.a, r.b, r.distance) for r in report.clearances.values()]
    fresh = run(False)
    [(_, _, distance)] = fresh
    assert distance == pytest.approx(3.0, abs=2 * interference.MESH_DEFLECTION)
    assert run(True) == fresh
