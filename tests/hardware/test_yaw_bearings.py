# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The yaw joint on two bearings: their seats in the floor's boss, the rings and spacers that locate them on the fixed
shaft, the bearing-load check that holds them against their C0 (and fails on a head tipping on one bearing, on
bearings too close together for their load, on an overload), and the circlip pliers' reach in the sequence."""
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from robogene_head import bearing_loads, geom, kinematics, massprops, sequence
from robogene_head.assembly import Assembly
from robogene_head.checks import assembly_sequence as chk
from robogene_head.geom import distance, location
from robogene_head.parts import head_frame, joint_encoders, neck, yaw_bearings
from robogene_head_model.params import ParameterError

from param_variants import edited


@pytest.fixture(scope="module")
def world(params):
    """The yaw parts of head and neck in the neck base's frame at the zero pose."""
    poses = kinematics.link_poses(params, {})
    parts = [p for p in head_frame.build(params) + neck.build(params) + joint_encoders.build(params)
             if p.name in ("head_floor", "neck_roll_stage", "neck_yaw_joint_pulley", "neck_yaw_joint_encoder",
                           "neck_yaw_encoder_magnet", "neck_yaw_encoder_bracket")
             or p.name.startswith(("neck_yaw_bearing_", "neck_yaw_spacer_", "neck_yaw_ring_"))]
    return {p.name: p.shape.moved(location(poses[p.link])) for p in parts}


def test_two_bearings_span_the_boss_and_sit_against_its_land(params, world):
    lay = yaw_bearings.layout(params)
    lower, upper = world["neck_yaw_bearing_lower"], world["neck_yaw_bearing_upper"]
    assert upper.Center().z - lower.Center().z == pytest.approx(params.geometry("yaw_bearings").num("span"))
    floor = world["head_floor"]
    for bearing in (lower, upper):
        assert distance(bearing, floor) < 1e-6                      # pressed in its seat
        assert bearing.intersect(floor).Volume() < 1e-3
    # the land between them: the floor's material reaches inside the outer rings' diameter there
    zy = params.joints["neck_yaw"].origin[2] + params.joints["neck_pitch"].origin[2] + params.joints["neck_roll"].origin[2]
    mid = zy + (lay.lower + lay.width + lay.upper) / 2
    probe = geom.tube("z", lay.outside - 0.2, lay.land_hole + 0.2, mid - 0.1, mid + 0.1)
    assert probe.intersect(floor).Volume() > 0.5 * probe.Volume()


@pytest.mark.parametrize("which", ["lower", "upper"])
def test_each_ring_stands_off_its_bearing_on_the_spacer(params, world, which):
    ring, spacer, bearing = (world[f"neck_yaw_{k}_{which}"] for k in ("ring", "spacer", "bearing"))
    outside, thickness = yaw_bearings.layout(params).spacer
    assert distance(ring, bearing) == pytest.approx(thickness)
    assert thickness >= neck.LUG_GAP
    assert distance(ring, spacer) < 1e-6 and distance(spacer, bearing) < 1e-6
    # the spacer bears on the inner ring's face alone, off the seal
    assert outside <= params.purchased("skf-61802-2RS").num("inner_ring_outside")
    assert spacer.BoundingBox().xlen == pytest.approx(outside)
    # the ring sits in its groove: it overlaps no part of the shaft
    assert ring.intersect(world["neck_roll_stage"]).Volume() < 1e-3
    assert spacer.intersect(world["neck_roll_stage"]).Volume() < 1e-3


def test_the_lower_rings_lugs_clear_the_turning_floor(params, world):
    """The lugs are not modelled: a cylinder of the ring's mounted size (d4) at the ring must keep the clearance
    minimum from the floor, which turns round it."""
    lay = yaw_bearings.layout(params)
    ring = params.purchased(lay.ring)
    box = world["neck_yaw_ring_lower"].BoundingBox()
    lugs = geom.cyl("z", ring.num("lug_outer_diameter"), box.zmin, box.zmax, (box.center.x, box.center.y))
    gap = params.geometry("clearances").num("minimum")
    assert distance(lugs, world["head_floor"]) >= gap - 1e-6
    assert distance(lugs, world["neck_yaw_joint_pulley"]) > 0


def test_the_sensor_faces_the_shaft_end(params, world):
    """The magnet sits flush in the shaft's top, past the upper ring; the board's IC faces it the encoder's gap
    above (joint_encoders' own placement); the bracket stands on the floor, off the boss."""
    end = world["neck_roll_stage"].BoundingBox().zmax
    floor_top = world["head_floor"].BoundingBox().zmin + params.geometry("head", "floor").num("thickness")
    assert end - floor_top == pytest.approx(yaw_bearings.shaft_end(params))
    assert end > world["neck_yaw_ring_upper"].BoundingBox().zmax
    assert world["neck_yaw_encoder_magnet"].BoundingBox().zmax == pytest.approx(end)
    assert world["neck_yaw_joint_encoder"].BoundingBox().zmin == pytest.approx(     # the IC's face
        end + params.geometry("joint_encoders").num("gap"))
    bracket = world["neck_yaw_encoder_bracket"]
    assert bracket.BoundingBox().zmin == pytest.approx(floor_top)
    assert distance(bracket, yaw_bearings.boss(params).moved(location(kinematics.link_poses(params, {})["head_frame"]))) \
        >= params.geometry("clearances").num("minimum") - 1e-6


@pytest.mark.parametrize("edit, message", [
    (lambda d: d["geometry"]["yaw_bearings"]["spacer"].update(thickness=0.1),
     r"geometry\.yaw_bearings\.spacer\.thickness: the din471-15x1 ring's lugs reach out to 22\.6.*this one: 0\.1"),
    (lambda d: d["geometry"]["yaw_bearings"]["spacer"].update(outside=21),
     r"geometry\.yaw_bearings\.spacer\.outside: 21 must be over the 15 mm shaft and within the skf-61802-2RS's inner "
     r"ring's face \(17\.5 across\)"),
    (lambda d: d["geometry"]["yaw_bearings"].update(span=5.5), r"geometry\.yaw_bearings\.span: 5\.5 leaves under 1 mm"),
    (lambda d: d["geometry"]["yaw_bearings"].update(land_hole=16), r"geometry\.yaw_bearings\.land_hole: 16 must clear"),
    (lambda d: d["purchased"]["din471-15x1"].update(shaft=12), r"din471-15x1 \(for a 12 mm shaft\) must fit"),
])
def test_a_seat_that_cannot_hold_its_bearings_is_refused(tmp_path, edit, message):
    with pytest.raises(ParameterError, match=message):
        yaw_bearings.layout(edited(tmp_path, edit))


@pytest.fixture(scope="module")
def props(params, assembly):
    return massprops.link_props(params, assembly.parts)


@pytest.mark.timeout(900)
def test_the_bearings_carry_the_head_with_their_static_safety(params, assembly, props):
    report = bearing_loads.analyse(params, assembly.parts, props)
    assert report.ok, bearing_loads.format_table(report)
    yaw = [b for b in report.loads if b.joint == "neck_yaw"]
    assert [b.bearing for b in yaw] == ["neck_yaw_bearing_lower", "neck_yaw_bearing_upper"]
    assert all(b.safety >= bearing_loads.required_safety(params) for b in yaw)
    # the statics behind it: at rest the bearings carry the head's weight along the axis and nothing across it;
    # pitched by 22 deg, the weight's component across the axis
    loaded = bearing_loads.drive_sizing.with_payloads(params, props)
    distal = ("head_frame", "eyes_tilt_link", "left_eye", "right_eye")
    weight = sum(loaded[link].mass for link in distal) * 9.80665
    still = {j: 0.0 for j in ("neck_pitch", "neck_roll", "neck_yaw")}
    for q, across in (({}, 0.0), ({"neck_pitch": 22.0}, weight * math.sin(math.radians(22)))):
        axial, force, _, _ = bearing_loads._loads_at(params, loaded, "neck_yaw", list(distal), list(still), still, q)[0]
        assert axial == pytest.approx(weight * math.cos(math.radians(q.get("neck_pitch", 0.0))))
        assert float(np.linalg.norm(force)) == pytest.approx(across, abs=1e-9)


@pytest.mark.timeout(900)
def test_a_head_on_one_bearing_fails_the_check(params, assembly, props):
    one = [p for p in assembly.parts if p.name != "neck_yaw_bearing_upper"]
    report = bearing_loads.analyse(params, one, props)
    assert not report.ok
    assert re.match(r"neck_yaw: 1 ball bearing on its axis carries a tipping moment of up to [0-9.]+ N m",
                    report.problems[0]), report.problems
    with pytest.raises(bearing_loads.BearingLoadError, match="unable to carry"):
        bearing_loads.enforce(report)


@pytest.mark.timeout(900)
def test_bearings_closer_together_carry_more_and_an_overload_fails(params, assembly, props, tmp_path):
    """The radial loads grow as the span shrinks; with a heavier payload the bearings fall below the static safety
    and the check names them."""
    base = {b.bearing: b for b in bearing_loads.analyse(params, assembly.parts, props).loads}
    close = edited(tmp_path, lambda d: d["geometry"]["yaw_bearings"].update(span=6))
    near = [p for p in head_frame.build(close) if p.name.startswith("neck_yaw_bearing_")]
    others = [p for p in assembly.parts if not p.name.startswith("neck_yaw_bearing_")]
    closer = {b.bearing: b for b in bearing_loads.analyse(close, others + near, props).loads}
    assert closer["neck_yaw_bearing_upper"].radial_N > 2 * base["neck_yaw_bearing_upper"].radial_N

    def heavy(d):
        d["geometry"]["yaw_bearings"].update(span=6)
        d["drive_sizing"]["payloads"][0].update(mass=12.0)
    overloaded = edited(tmp_path, heavy)
    report = bearing_loads.analyse(overloaded, others + near, props)
    assert not report.ok
    low = [b.bearing for b in report.loads if b.safety < report.required]
    assert "neck_yaw_bearing_upper" in low
    with pytest.raises(bearing_loads.BearingLoadError, match=r"neck_yaw_bearing_upper \([0-9.]+\)"):
        bearing_loads.enforce(report)


def test_the_package_reports_the_bearing_loads(fab):
    report = json.loads((fab / "reports" / "bearing-loads.json").read_text())
    assert report["ok"] and not report["problems"]
    assert {b["bearing"] for b in report["bearings"]} >= {"neck_yaw_bearing_lower", "neck_yaw_bearing_upper"}
    assert "neck_yaw_bearing_upper" in (fab / "reports" / "bearing-loads.txt").read_text()


def _ring_step(params, before_encoder: bool, straddles: bool):
    parts = {p.name: p for p in neck.build(params) + head_frame.build(params) + joint_encoders.build(params)}
    chosen = [parts[n] for n in ("neck_roll_stage", "neck_yaw_ring_upper", "neck_yaw_joint_encoder")]
    ring = {"name": "ring", "parts": ["neck_yaw_ring_upper"], "flexible": "spread with pliers",
            "access": {"driver": "circlip-pliers-ext-15", "along": [0, 0, 1]}}
    if straddles:
        ring["access"]["straddles"] = ["neck_roll_stage"]
    encoder = {"name": "encoder", "parts": ["neck_yaw_joint_encoder"], "from": [[0, 0, 120]]}
    steps = [{"name": "stage", "parts": ["neck_roll_stage"], "fixture": True}]
    steps += [ring, encoder] if before_encoder else [encoder, ring]
    data = {"drivers": {"circlip-pliers-ext-15": {"blade": 24, "length": 55, "handle": 40}},
            "screw_drivers": {}, "subassemblies": {}, "sequence": steps}
    seq = sequence.parse(data, Path("variant.yaml"), [p.name for p in chosen])
    return chk.check(params, Assembly(params, chosen), seq)


def test_the_upper_rings_pliers_reach_it_only_before_the_sensor(params):
    """The pliers go round the shaft (access.straddles), and are still checked against everything else: with the
    sensor over the shaft first they hit it; without straddles they would hit the shaft itself."""
    report = _ring_step(params, before_encoder=True, straddles=True)
    assert report.ok, chk.format_report(report)
    report = _ring_step(params, before_encoder=False, straddles=True)
    assert report.problems and re.search(r"hits neck_yaw_joint_encoder", report.problems[0].what), report.problems
    report = _ring_step(params, before_encoder=True, straddles=False)
    assert report.problems and re.search(r"hits neck_roll_stage", report.problems[0].what), report.problems
