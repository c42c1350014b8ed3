# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The belt-driven joints' pulleys take their torque through set screws in a hub: the torque_paths data names what
the CAD draws (the bore is the shaft, as many set screws as drawn, each reaching a flat on the shaft radially), the
check passes them and fails the same joints on a plain bore or one small screw, and the screws' key reaches them."""
import copy
import math
from pathlib import Path

import numpy as np
import pytest
import yaml

from robogene_head import sequence, torque_path
from robogene_head.assembly import Assembly
from robogene_head.checks import assembly_sequence as chk
from robogene_head.checks import interference
from robogene_head.geom import distance
from robogene_head.parts import eyes, mounts, neck
from robogene_head_model.params import ParameterError, parse

from param_variants import edited

# joint -> (the builder that draws its joint pulley, the part whose shaft the pulley sits on)
JOINTS = {"neck_yaw": (neck.build, "neck_roll_stage"), "eyes_tilt": (eyes.build, "eyes_tilt_frame")}


def _joint_side(params, joint):
    (item,) = [e for e in params.root.raw("torque_paths")[joint] if e["at"] == "joint"]
    return item


def _bore(shape) -> float:
    """The smallest cylindrical face about the pulley's own axis (its frame's z): its bore."""
    radii = []
    for face in shape.Faces():
        if face.geomType() != "CYLINDER":
            continue
        cylinder = face._geomAdaptor().Cylinder()
        d, c = cylinder.Axis().Direction(), cylinder.Location()
        if abs(abs(d.Z()) - 1) < 1e-9 and math.hypot(c.X(), c.Y()) < 1e-6:
            radii.append(cylinder.Radius())
    return 2 * min(radii)


def mismatches(params, joint) -> list[str]:
    """What the joint's torque_paths entry past the belt says that the CAD does not draw."""
    build, shaft_part = JOINTS[joint]
    parts = {p.name: p for p in build(params)}
    pulley, shaft = parts[f"{joint}_joint_pulley"], parts[shaft_part]
    screws = [p for n, p in parts.items() if n.startswith(f"{joint}_pulley_set_screw_")]
    item, problems = _joint_side(params, joint), []
    if item["element"] != "set_screw":
        problems.append(f"element {item['element']}, the CAD draws set screws")
        return problems
    if item["count"] != len(screws):
        problems.append(f"count {item['count']}, the CAD draws {len(screws)}")
    if {s.design for s in screws} != {item["screw"]}:
        problems.append(f"screw {item['screw']}, the CAD draws {sorted({s.design for s in screws})}")
    placed = pulley.placement
    bore = _bore(pulley.local)
    if not math.isclose(item["shaft"], bore, abs_tol=1e-6):
        problems.append(f"shaft {item['shaft']}, the pulley's bore is {bore:g}")
    fit = params.geometry("clearances").num("fit_tolerance")
    axis_origin = np.array(placed.toTuple()[0])
    matrix = placed.wrapped.Transformation()
    axis = np.array([matrix.Value(i, 3) for i in (1, 2, 3)])
    flats = [f for f in shaft.shape.Faces() if f.geomType() == "PLANE"]
    for s in screws:
        if distance(s.shape, shaft.shape) > fit:
            problems.append(f"{s.name} does not reach the shaft")
        elif not any(distance(s.shape, f) <= fit for f in flats):
            problems.append(f"{s.name} does not bear on a flat")
        if s.shape.intersect(shaft.shape).Volume() > interference.VOLUME_TOLERANCE:
            problems.append(f"{s.name} cuts into the shaft")
        t = s.placement.wrapped.Transformation()
        origin = np.array([t.Value(i, 4) for i in (1, 2, 3)])
        direction = np.array([t.Value(i, 3) for i in (1, 2, 3)])
        # radial: the screw's axis meets the pulley's axis at right angles
        offset = origin - axis_origin
        normal = np.cross(direction, axis)
        if abs(direction @ axis) > 1e-9 or abs(offset @ normal) / np.linalg.norm(normal) > 1e-6:
            problems.append(f"{s.name} is not radial")
    return problems


@pytest.mark.parametrize("joint", JOINTS)
def test_the_torque_path_names_what_the_cad_draws(params, joint):
    assert mismatches(params, joint) == []
    assert len(mounts.set_screw_angles(params, joint)) == _joint_side(params, joint)["count"] == 2


def test_a_hub_drawn_with_one_screw_no_longer_matches_the_data(tmp_path):
    """The comparison sees a difference: the CAD with one set screw in the yaw hub, the data still saying two."""
    def one_screw(data):
        data["geometry"]["pulleys"]["joint_hub"]["set_screw_angles"]["yaw"] = [0]
    assert mismatches(edited(tmp_path, one_screw), "neck_yaw") == ["count 2, the CAD draws 1"]

    def wider_bore(data):
        next(e for e in data["torque_paths"]["eyes_tilt"] if e["at"] == "joint")["shaft"] = 8
    assert mismatches(edited(tmp_path, wider_bore), "eyes_tilt") == ["shaft 8, the pulley's bore is 6"]


# A weaker set screw for the variants: an M2 taken, like the M3, at the next smaller inch size of the same table
# (#1: 65 lbf).
M2 = {"kind": "set_screw", "diameter": 2, "length": 3, "holding_force_N": 289, "mass": 0.0001}


def test_the_joint_pulleys_pass_where_a_plain_bore_or_one_small_screw_fails(params, tmp_path):
    """Yaw: 2 x 712 N at the Ø15 shaft's radius is 10.7 N m against the drive's 0.533 N m peak there (its 550 mA
    limit through the 20/14 XL stage); a plain bore fails, while one M2 (2.2 N m, margin 4.1) would now pass. Tilt:
    4.3 N m against 0.45 N m (the 24/14 XL stage); a plain bore fails, while one M2 (0.87 N m, margin 1.94) would
    now pass."""
    report = torque_path.analyse(params)
    for joint in JOINTS:
        (hub,) = [e for e in report.elements if e.joint == joint and e.at == "joint"]
        assert hub.element == "set_screw" and hub.margin >= report.required, hub
    assert [e for e in report.elements if e.joint == "neck_yaw" and e.at == "joint"][0].capacity_Nm == \
        pytest.approx(2 * 712 * 7.5 / 1000)

    one_m2 = lambda e: e.update(count=1, screw="iso4029-M2x3")   # noqa: E731
    plain = lambda e: (e.update(element="plain", length=8), e.pop("count"), e.pop("screw"))   # noqa: E731
    for joint, weakenings in (("neck_yaw", (plain,)), ("eyes_tilt", (plain,))):
        index = [e["at"] for e in params.root.raw("torque_paths")[joint]].index("joint")
        for weaken in weakenings:
            def edit(data, joint=joint, weaken=weaken):
                data["purchased"]["iso4029-M2x3"] = M2
                weaken(next(e for e in data["torque_paths"][joint] if e["at"] == "joint"))
            weak = torque_path.analyse(edited(tmp_path, edit))
            failed = [e for e in weak.failures() if e.joint == joint and e.at == "joint"]
            assert len(failed) == 1, (joint, weak.elements)
            with pytest.raises(torque_path.TorquePathError, match=rf"{joint}\[{index}\]"):
                torque_path.enforce(weak)

    def tilt_one_m2(data):
        data["purchased"]["iso4029-M2x3"] = M2
        one_m2(next(e for e in data["torque_paths"]["eyes_tilt"] if e["at"] == "joint"))
    (hub,) = [e for e in torque_path.analyse(edited(tmp_path, tilt_one_m2)).elements
              if e.joint == "eyes_tilt" and e.at == "joint"]
    assert hub.margin == pytest.approx(289 * 3 / 1000 / (0.261 * 24 / 14), rel=0.01)

    def yaw_one_m2(data):
        data["purchased"]["iso4029-M2x3"] = M2
        one_m2(next(e for e in data["torque_paths"]["neck_yaw"] if e["at"] == "joint"))
    (hub,) = [e for e in torque_path.analyse(edited(tmp_path, yaw_one_m2)).elements
              if e.joint == "neck_yaw" and e.at == "joint"]
    assert hub.margin == pytest.approx(289 * 7.5 / 1000 / (0.373 * 20 / 14), rel=0.01)


@pytest.mark.parametrize("edit, message", [
    (lambda d: d["geometry"]["pulleys"]["joint_hub"].update(wall=3),
     r"geometry\.pulleys\.joint_hub\.wall: 3 is shorter than the iso4029-M3x4 set screw"),
    (lambda d: d["geometry"]["pulleys"]["joint_hub"].update(length=3),
     r"geometry\.pulleys\.joint_hub\.length: 3 leaves no metal"),
    (lambda d: d["geometry"]["pulleys"]["joint_hub"].update(set_screw="iso7380-M3x8"),
     r"geometry\.pulleys\.joint_hub\.set_screw: 'iso7380-M3x8' is a screw, expected a set_screw"),
    (lambda d: d["geometry"]["pulleys"]["joint_hub"].update(flat_depth=0.05),
     r"geometry\.pulleys\.joint_hub\.flat_depth: 0\.05 on a 6 mm shaft does not make a flat as wide as the M3"),
    (lambda d: d["geometry"]["pulleys"]["joint_hub"]["set_screw_angles"].update(tilt=[]),
     r"geometry\.pulleys\.joint_hub\.set_screw_angles\.tilt: expected a list"),
])
def test_a_wrong_joint_hub_is_named(tmp_path, edit, message):
    with pytest.raises(ParameterError, match=message):
        eyes.build(edited(tmp_path, edit))


def _yaw_set_screws_reached(params, angles):
    """The yaw pulley's step on the neck as the sequence has it then (pitch stage, roll stage and roll drive in
    place): the pulley goes down onto the yaw shaft, then its set screws are tightened with the 1.5 mm key."""
    data = copy.deepcopy(params.root._data)
    data["geometry"]["pulleys"]["joint_hub"]["set_screw_angles"]["yaw"] = angles
    variant = parse(data, "variant", params.path)
    parts = {p.name: p for p in neck.build(variant)}
    there = ["neck_pitch_stage", "neck_roll_stage"] + [n for n in parts if n.startswith(("neck_roll_", "roll_mount"))
                                                        and n != "neck_roll_stage"]
    pulley = ["neck_yaw_joint_pulley"] + [n for n in parts if n.startswith("neck_yaw_pulley_set_screw_")]
    steps = [{"name": "neck", "parts": there, "fixture": True},
             {"name": "yaw pulley", "parts": ["neck_yaw_joint_pulley"], "from": [[0, 0, 70]], "fits": ["neck_roll_stage"],
              "fasteners": ["neck_yaw_pulley_set_screw_*"]}]
    data = {"drivers": {"hex-1.5": {"blade": 1.8, "length": 60, "handle": 20}},
            "screw_drivers": {"iso4029-M3": "hex-1.5"}, "subassemblies": {}, "sequence": steps}
    chosen = [parts[n] for n in dict.fromkeys(there + pulley)]
    seq = sequence.parse(data, Path("variant.yaml"), [p.name for p in chosen])
    return chk.check(variant, Assembly(variant, chosen), seq)


# Two assembly-sequence sweeps with the key along each screw: about 190 s on a 2-core machine under load.
@pytest.mark.timeout(600)
def test_the_yaw_set_screws_are_reached_where_drawn_and_not_behind_the_roll_drive(params):
    """At 0 and 90 deg the key comes in from the front and the side; turned to 180 deg, the first screw faces the
    roll drive's mount plate behind the yaw shaft and the key cannot reach it."""
    assert mounts.set_screw_angles(params, "neck_yaw") == [0.0, 90.0]
    report = _yaw_set_screws_reached(params, [0, 90])
    assert report.ok, chk.format_report(report)
    report = _yaw_set_screws_reached(params, [180, 90])
    assert [p.what.split(":")[0] for p in report.problems] == ["neck_yaw_pulley_set_screw_0 (hex-1.5)"]
    assert "hits neck_roll_motor_mount" in report.problems[0].what


def test_a_yaw_hub_longer_than_the_room_above_the_roll_stage_is_named(tmp_path):
    def long_hub(data):
        data["geometry"]["pulleys"]["joint_hub"]["length"] = 7
    with pytest.raises(ParameterError, match=r"geometry\.pulleys\.joint_hub\.length: 7 reaches into the roll stage: "
                                             r"the yaw joint pulley stands 6\.7 above it"):
        neck.build(edited(tmp_path, long_hub))
