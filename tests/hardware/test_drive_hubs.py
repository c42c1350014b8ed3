# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The pitch and roll drives' hubs: what torque_paths: says of them (screw, count, shaft) is what the CAD builds,
read back from the built parts (the tapped holes in the stages, the set screws' points on the gearheads' shafts);
the check refuses a weakened variant; the screws' drivers reach them at their assembly step, and do not when the
left upright has no access holes."""
import copy
from pathlib import Path

import numpy as np
import pytest
import yaml

from robogene_head import sequence, threads, torque_path
from robogene_head.assembly import Assembly
from robogene_head.checks import assembly_sequence as chk
from robogene_head.parts import neck
from robogene_head_model.params import DEFAULT_PATH, ParameterError, parse

from param_variants import edited

STAGES = {"neck_pitch": ("neck_pitch_stage", (0.0, 1.0, 0.0)), "neck_roll": ("neck_roll_stage", (1.0, 0.0, 0.0))}


@pytest.fixture(scope="module")
def neck_parts(params):
    return {p.name: p for p in neck.build(params)}


def _axis_of(part) -> tuple[np.ndarray, np.ndarray]:
    """The placed set screw's socket-end point and its axis (towards its point), in its link's frame."""
    m = part.placement.wrapped.Transformation()
    origin = np.array([m.Value(1, 4), m.Value(2, 4), m.Value(3, 4)])
    axis = np.array([m.Value(1, 3), m.Value(2, 3), m.Value(3, 3)])
    return origin, axis


def _built_path(params, parts: dict, joint: str) -> dict:
    """What the CAD builds between the joint's gearhead shaft and its stage, read from the parts."""
    stage, axis = STAGES[joint]
    screws = sorted(n for n in parts if n.startswith(f"{joint}_hub_screw_"))
    # tapped holes whose axis crosses the joint axis (which runs through the link frame's origin): the nearest point
    # of such a hole's axis to the origin lies on the joint axis
    holes = [h for h in threads.tapped_holes(params, list(parts.values())).get(stage, [])
             if abs(np.dot(h.direction, axis)) < 1e-9 and np.linalg.norm(np.cross(h.point, axis)) < 1e-6]
    # cylindrical faces on the joint axis: the bore the gearhead's shaft goes in, the journals, the hub
    bores = {round(d, 4) for d, point, direction, _, _ in threads._cylinders(parts[stage].local)
             if np.linalg.norm(np.cross(direction, axis)) < 1e-9 and np.linalg.norm(np.cross(point, axis)) < 1e-6}
    return {"screws": [parts[n].design for n in screws], "holes": [h.thread for h in holes],
            "shaft": params.purchased(params.drive(joint).text("gearhead")).num("shaft_diameter"), "bores": bores}


def _declared(params, joint: str) -> dict:
    (entry,) = params.root.node("torque_paths").raw(joint)
    return entry


def disagreements(params, parts: dict, joint: str) -> list[str]:
    """Where torque_paths.<joint> and the built parts differ."""
    entry, built = _declared(params, joint), _built_path(params, parts, joint)
    out = []
    if entry["element"] != "set_screw":
        out.append(f"element {entry['element']} (the CAD draws set screws)")
    if built["screws"] != [entry["screw"]] * entry["count"]:
        out.append(f"{entry['count']} x {entry['screw']} declared, the CAD places {built['screws']}")
    thread = f"M{params.purchased(entry['screw']).num('diameter'):g}"
    if built["holes"] != [thread] * entry["count"]:
        out.append(f"{entry['count']} {thread} holes declared, the stage has {built['holes']}")
    if entry["shaft"] != "gearhead" or built["shaft"] not in built["bores"]:
        out.append(f"shaft {entry['shaft']}: no {built['shaft']:g} mm bore in the stage")
    return out


@pytest.mark.parametrize("joint", ["neck_pitch", "neck_roll"])
def test_torque_paths_says_what_the_cad_builds(params, neck_parts, joint):
    assert disagreements(params, neck_parts, joint) == []
    assert _declared(params, joint)["count"] == 2 and len(_built_path(params, neck_parts, joint)["holes"]) == 2


@pytest.mark.parametrize("joint", ["neck_pitch", "neck_roll"])
def test_each_set_screw_presses_on_the_gearhead_shaft(params, neck_parts, joint):
    """Each screw points at the joint axis, its point on the shaft (touching, not in it), where the shaft is, over the
    joint's range: the drive's gearhead solid, on the link the drive is fixed to, against the screws on the stage."""
    assembly = Assembly(params, list(neck_parts.values()))
    lo, hi = params.control_limits[joint]
    for angle in (lo, 0.0, hi):
        placed = {p.part.name: p.shape for p in assembly.pose({joint: angle})}
        for name in (f"{joint}_hub_screw_0", f"{joint}_hub_screw_1"):
            assert placed[name].distance(placed[f"{joint}_gearhead"]) < 1e-3, (name, angle)
            assert placed[name].intersect(placed[f"{joint}_gearhead"]).Volume() < 1e-3, (name, angle)
            # in its tapped hole: touching the stage, not cutting into it
            stage = placed[STAGES[joint][0]]
            assert placed[name].distance(stage) < 1e-3 and placed[name].intersect(stage).Volume() < 1e-3
    shaft = params.purchased(params.drive(joint).text("gearhead")).num("shaft_diameter")
    directions = []
    for name in (f"{joint}_hub_screw_0", f"{joint}_hub_screw_1"):
        part = neck_parts[name]
        origin, axis = _axis_of(part)
        directions.append(axis)
        length = params.purchased(part.design).num("length")
        assert np.linalg.norm(np.cross(axis, STAGES[joint][1])) == pytest.approx(1)       # across the joint axis
        tip = origin + axis * length
        # the point lies on the shaft's surface: shaft/2 from the joint axis
        along = np.dot(tip, STAGES[joint][1]) * np.array(STAGES[joint][1])
        assert np.linalg.norm(tip - along) == pytest.approx(shaft / 2, abs=1e-6)
    assert abs(np.dot(*directions)) < 1e-9                                               # 90 deg apart


def test_the_check_sees_a_cad_that_differs_from_the_data(tmp_path, params, neck_parts):
    """A torque_paths entry with a third screw the CAD does not draw, or a smaller one, is caught."""
    data = yaml.safe_load(DEFAULT_PATH.read_text())
    data["torque_paths"]["neck_pitch"][0]["count"] = 3
    data["purchased"]["iso4029-M3x4"] = {"kind": "set_screw", "diameter": 3, "length": 4, "holding_force_N": 890,
                                         "mass": 0.0002}
    data["torque_paths"]["neck_roll"][0]["screw"] = "iso4029-M3x4"
    variant = parse(data, "variant", params.path)
    assert disagreements(variant, neck_parts, "neck_pitch") == [
        "3 x iso4029-M4x4 declared, the CAD places ['iso4029-M4x4', 'iso4029-M4x4']",
        "3 M4 holes declared, the stage has ['M4', 'M4']"]
    assert "M3 holes declared" in disagreements(variant, neck_parts, "neck_roll")[1]


def test_pitch_and_roll_pass_and_a_weakened_hub_fails(tmp_path, params):
    """Two M4 set screws hold 2 x 1112 N x 3 mm = 6.67 N m: 2.06 times pitch's peak, 3.08 times roll's (its continuous
    rating: its 1 A limit gives less). One screw fewer on pitch (3.34 N m, 1.03 times its peak), or two M2 on roll
    (378 N each: 2.27 N m, 1.05 times its peak), is below the margin, and the check says which; one M4 on roll
    (1.54 times its peak) would pass."""
    report = torque_path.analyse(params)
    for joint in ("neck_pitch", "neck_roll"):
        (element,) = [e for e in report.elements if e.joint == joint]
        assert element.capacity_Nm == pytest.approx(2 * 1112 * 3 / 1000)
        assert element not in report.failures() and element.margin >= report.required

    def one_screw(data):
        for joint in ("neck_pitch", "neck_roll"):
            data["torque_paths"][joint][0]["count"] = 1
    weak = torque_path.analyse(edited(tmp_path, one_screw))
    assert {e.joint for e in weak.failures()} == {"neck_pitch"}
    with pytest.raises(torque_path.TorquePathError, match=r"neck_pitch\[0\] set_screw \(3\.336 of 3\.234 N m\)"):
        torque_path.enforce(weak)

    def m2(data):
        data["torque_paths"]["neck_roll"][0]["screw"] = "iso4029-M2x3"
    smaller = torque_path.analyse(edited(tmp_path, m2))
    assert [e.joint for e in smaller.failures()].count("neck_roll") == 1
    assert "neck_pitch" not in [e.joint for e in smaller.failures()]


@pytest.mark.parametrize("edit, where", [
    (lambda g: g.update(diameter=14), r"geometry\.drive_hubs\.diameter: the iso4029-M4x4s on the 6 mm shaft stand "
                                        r"out of a 14 mm hub"),
    (lambda g: g["neck_roll"].update(directions=["x", "y"]), r"geometry\.drive_hubs\.neck_roll\.directions"),
    (lambda g: g["neck_pitch"].update(directions=["z", "z"]), r"geometry\.drive_hubs\.neck_pitch\.directions"),
    (lambda g: g["neck_pitch"].update(access=4), r"geometry\.drive_hubs\.neck_pitch\.access: a 4 mm hole"),
    (lambda g: g["neck_roll"].update(from_tip=9), r"geometry\.drive_hubs\.neck_roll: the roll hub"),
    (lambda g: g["neck_pitch"].update(from_tip=1), r"geometry\.drive_hubs\.neck_pitch\.from_tip"),
    (lambda g: g.update(screw="iso7380-M3x8"), r"geometry\.drive_hubs\.screw: iso7380-M3x8 is a screw"),
])
def test_a_wrong_hub_is_named(params, edit, where):
    data = copy.deepcopy(params.root._data)
    edit(data["geometry"]["drive_hubs"])
    with pytest.raises(ParameterError, match=where):
        neck.build(parse(data, "variant", params.path))


def _check(params, parts, steps, subassemblies=None):
    data = {"drivers": {"hex-2": {"blade": 2.4, "length": 75, "handle": 25},
                        "hex-2-long": {"blade": 2.4, "length": 150, "handle": 25}},
            "screw_drivers": {"iso7380-M3": "hex-2", "iso4029-M4": "hex-2"},
            "subassemblies": subassemblies or {}, "sequence": steps}
    seq = sequence.parse(data, Path("variant.yaml"), [p.name for p in parts])
    return chk.check(params, Assembly(params, parts), seq)


PITCH_PARTS = ("neck_base_plate", "neck_upright_left", "neck_pitch_stage", "neck_pitch_motor_mount",
               "neck_pitch_gearhead", "neck_pitch_hub_screw_0", "neck_pitch_hub_screw_1")
PITCH_STEPS = [{"name": "plate", "parts": ["neck_base_plate"], "fixture": True},
               {"name": "left upright", "parts": ["neck_upright_left"], "from": [[0, 0, 30]]},
               {"name": "pitch stage", "parts": ["neck_pitch_stage"], "from": [[0, -110, 0]]},
               {"name": "mount", "parts": ["neck_pitch_motor_mount"], "from": [[0, 30, 0]]},
               {"name": "drive", "parts": ["neck_pitch_gearhead"], "from": [[0, 30, 0]], "fits": ["neck_pitch_stage"]},
               {"name": "set screws", "fasteners": ["neck_pitch_hub_screw_*"]}]


def test_the_pitch_set_screws_are_reached_through_the_upright_and_not_without_its_holes(params, neck_parts):
    """With the drive on, the pitch hub turns inside the left upright: the 2 mm key reaches each set screw through
    the upright's access holes, and without them (a variant with no access) it hits the upright."""
    parts = [neck_parts[n] for n in PITCH_PARTS]
    report = _check(params, parts, PITCH_STEPS)
    assert report.ok, chk.format_report(report)
    assert [t["tool"] for t in report.steps[-1].tools] == ["neck_pitch_hub_screw_0 (hex-2)",
                                                           "neck_pitch_hub_screw_1 (hex-2)"]
    data = copy.deepcopy(params.root._data)
    del data["geometry"]["drive_hubs"]["neck_pitch"]["access"]
    closed = parse(data, "variant", params.path)
    built = {p.name: p for p in neck.build(closed)}
    report = _check(closed, [built[n] for n in PITCH_PARTS], PITCH_STEPS)
    assert [p.step for p in report.problems] == ["step 6 'set screws'"] * 2
    for k, problem in enumerate(report.problems):
        assert problem.what.startswith(f"neck_pitch_hub_screw_{k} (hex-2): the 4 mm tool along the axis hits "
                                       "neck_upright_left"), problem.what


def test_the_roll_set_screws_are_reached_between_the_rear_lug_and_the_roll_stage(params, neck_parts):
    names = ("neck_pitch_stage", "neck_roll_stage", "neck_roll_motor_mount", "neck_roll_gearhead",
             "neck_roll_hub_screw_0", "neck_roll_hub_screw_1")
    steps = [{"name": "stage", "parts": ["neck_pitch_stage"], "fixture": True},
             {"name": "roll stage", "parts": ["neck_roll_stage"], "from": [[60, 0, 0]]},
             {"name": "mount", "parts": ["neck_roll_motor_mount"], "from": [[-30, 0, 0]]},
             {"name": "drive", "parts": ["neck_roll_gearhead"], "from": [[-30, 0, 0]], "fits": ["neck_roll_stage"]},
             {"name": "set screws", "fasteners": ["neck_roll_hub_screw_*"]}]
    report = _check(params, [neck_parts[n] for n in names], steps)
    assert report.ok, chk.format_report(report)
    assert len(report.steps[-1].tools) == 2
