# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The assembly sequence: the package's check passed and drew every step; the checker fails, naming the step
and the parts, on variants that cannot be built: a part that cannot be inserted (the design this sequence
replaced), a part too wide for its slot (a parameter variant), a screw its driver cannot reach, a contact
that is not a declared fit, a start that is not outside, a part left out of the sequence, a set screw whose key
cannot get out through the eye cup."""
import copy
import json
import re
from pathlib import Path

import numpy as np
import pytest
import yaml
from OCP.BRepMesh import BRepMesh_IncrementalMesh

from robogene_head import fab as fab_build
from robogene_head import geom
from robogene_head import sequence
from robogene_head.assembly import Assembly
from robogene_head.cache import Cache
from robogene_head.checks import assembly_sequence as chk
from robogene_head_model.params import parse
from robogene_head.parts import eyes, head_frame, neck
from robogene_head.parts.base import Part, loc
from robogene_head.progress import Progress

from param_variants import edited


def test_package_check_passed_and_drew_every_step(fab, params):
    report = json.loads((fab / "reports" / "assembly.json").read_text())
    assert report["ok"] and report["problems"] == []
    parts = json.loads((fab / "parts.json").read_text())
    names = [n for d in parts for n in d["instances"]]
    seq = sequence.load(names)
    assert [s["step"] for s in report["steps"]] == [s.label for s in seq.steps()]
    # every screw was reached by its driver, every pressed bearing by its arbor, every circlip by its pliers
    tools = [t["tool"] for s in report["steps"] for t in s["tools"]]
    steps = seq.steps()
    assert len(tools) == sum(len(s.fasteners) + s.press + bool(s.access) for s in steps)
    assert {f"{f} (" for s in steps for f in s.fasteners} <= {t.split("(")[0] + "(" for t in tools}
    swept = [s for s in report["steps"] if not s["note"]]
    assert swept and all(s["samples"] > 1 for s in swept)
    folder = fab / "assembly" / "steps"
    pictures = sorted(folder.glob("*.png"))
    assert len(pictures) == len(seq.steps())
    assert all(p.stat().st_size > 10_000 for p in pictures)
    page = (folder / "README.md").read_text()
    assert all(p.name in page for p in pictures)


@pytest.fixture(scope="module")
def neck_parts(params):
    return {p.name: p for p in neck.build(params)}


def _check(params, parts, steps, subassemblies=None):
    names = [p.name for p in parts]
    data = {"drivers": {"hex-2": {"blade": 2.4, "length": 75, "handle": 25},
                        "hex-2-long": {"blade": 2.4, "length": 150, "handle": 25},
                        "hex-1.5": {"blade": 1.8, "length": 60, "handle": 20}},
            "screw_drivers": {"iso7380-M3": "hex-2", "iso4762-M2": "hex-1.5"},
            "subassemblies": subassemblies or {}, "sequence": steps}
    seq = sequence.parse(data, Path("variant.yaml"), names)
    return chk.check(params, Assembly(params, parts), seq)


ROLL_STAGE = [{"name": "roll stage", "parts": ["neck_roll_stage"], "fixture": True},
              {"name": "roll bearing", "parts": ["neck_roll_bearing_front"], "from": [[20, 0, 0]],
               "fits": ["neck_roll_stage"], "press": "inner"}]


def test_the_roll_stage_goes_in_before_the_front_lug(params, neck_parts):
    parts = [neck_parts[n] for n in ("neck_pitch_stage", "neck_roll_stage", "neck_pitch_front_lug",
                                     "neck_roll_bearing_front")]
    good = [{"name": "stage", "parts": ["neck_pitch_stage"], "fixture": True},
            {"name": "roll stage", "subassembly": "roll", "from": [[60, 0, 0]]},
            {"name": "lug", "parts": ["neck_pitch_front_lug"], "from": [[30, 0, 0]],
             "fits": ["neck_roll_bearing_front", "neck_pitch_stage"]}]
    report = _check(params, parts, good, {"roll": ROLL_STAGE})
    assert report.ok, chk.format_report(report)
    # The old order: the lug on first, then the roll stage with its integral shafts cannot get between the lugs.
    bad = [good[0], good[2], good[1]]
    report = _check(params, parts, bad, {"roll": ROLL_STAGE})
    assert not report.ok
    [problem] = report.problems
    # It runs into the front lug (its bearing into the lug's bore, or its body against the lug).
    assert problem.step == "step 3 'roll stage'"
    assert re.match(r"(neck_roll_stage|neck_roll_bearing_front) (touches|collides with) neck_pitch_front_lug "
                    r"[0-9.]+ mm along its path", problem.what), problem.what


def test_a_pitch_stage_wider_than_the_uprights_gap_is_caught(params):
    data = copy.deepcopy(params.root._data)
    data["geometry"]["neck_pitch_stage"]["body"]["width"] = 66     # the uprights stand 64 apart
    wide = parse(data, "variant", params.path)
    parts = {p.name: p for p in neck.build(wide)}
    chosen = [parts[n] for n in ("neck_base_plate", "neck_upright_left", "neck_pitch_stage")]
    steps = [{"name": "plate", "parts": ["neck_base_plate"], "fixture": True},
             {"name": "left upright", "parts": ["neck_upright_left"], "from": [[0, 0, 30]]},
             {"name": "pitch stage", "parts": ["neck_pitch_stage"], "from": [[0, -110, 0]]}]
    report = _check(wide, chosen, steps)
    assert [p.step for p in report.problems] == ["step 3 'pitch stage'"]
    assert re.match(r"neck_pitch_stage (touches|collides with) neck_upright_left", report.problems[0].what)


def test_a_screw_the_driver_cannot_reach_is_caught(params, tmp_path):
    """The tilt coupling's clamp screws go in from above through the jackshaft housing's window; a window narrower
    than their heads leaves them no way in."""
    def steps(p):
        parts = {q.name: q for q in head_frame.build(p)}
        chosen = [parts[n] for n in ["eyes_tilt_jackshaft_housing", "eyes_tilt_coupling",
                                     "eyes_tilt_coupling_screw_0", "eyes_tilt_coupling_screw_1"]]
        housing = {"name": "housing", "parts": ["eyes_tilt_jackshaft_housing"], "fixture": True}
        coupling = {"name": "coupling", "parts": ["eyes_tilt_coupling"], "from": [[0, -50, 0]],
                    "fits": ["eyes_tilt_jackshaft_housing"]}
        fixing = {"name": "screws", "fasteners": ["eyes_tilt_coupling_screw_*"]}
        return _check(p, chosen, [housing, coupling, fixing])
    assert steps(params).ok
    narrow = edited(tmp_path, lambda data: data["geometry"]["tilt_jackshaft"]["housing"].update(window=2))
    report = steps(narrow)
    assert report.problems and report.problems[0].step == "step 3 'screws'"
    assert re.match(r"eyes_tilt_coupling_screw_0 \(hex-1.5\): .* hits eyes_tilt_jackshaft_housing",
                    report.problems[0].what)


def test_a_bearing_pressed_onto_a_shaft_is_pressed_by_its_inner_ring(params):
    """The jackshaft's bearings are pressed on their inner rings: a sleeve round the shaft reaches them, where an
    arbor on the outer ring, the way a bearing goes into a housing, would have to pass through the shaft."""
    parts = {q.name: q for q in head_frame.build(params)}
    chosen = [parts["eyes_tilt_jackshaft"], parts["eyes_tilt_jackshaft_bearing_fixed"]]
    shaft = {"name": "shaft", "parts": ["eyes_tilt_jackshaft"], "fixture": True}
    press = {"name": "bearing", "parts": ["eyes_tilt_jackshaft_bearing_fixed"], "from": [[0, 40, 0]],
             "fits": ["eyes_tilt_jackshaft"], "press": "inner"}
    assert _check(params, chosen, [shaft, press]).ok
    report = _check(params, chosen, [shaft, dict(press, press="outer")])
    assert re.match(r"press arbor for eyes_tilt_jackshaft_bearing_fixed: .* hits eyes_tilt_jackshaft",
                    report.problems[0].what)


def test_a_contact_that_is_not_a_declared_fit_is_caught(params, neck_parts):
    parts = [neck_parts[n] for n in ("neck_roll_stage", "neck_roll_bearing_front")]
    steps = copy.deepcopy(ROLL_STAGE)
    del steps[1]["fits"]     # the bearing goes onto its journal
    report = _check(params, parts, steps)
    assert len(report.problems) == 1
    assert "neck_roll_bearing_front touches neck_roll_stage" in report.problems[0].what


def test_a_start_inside_the_assembly_is_caught(params, neck_parts):
    parts = [neck_parts[n] for n in ("neck_roll_stage", "neck_roll_bearing_front")]
    steps = copy.deepcopy(ROLL_STAGE)
    steps[1]["from"] = [[2, 0, 0]]
    report = _check(params, parts, steps)
    assert "is not outside" in report.problems[0].what


def test_a_bearing_pressed_across_its_axis_is_caught(params, neck_parts):
    parts = [neck_parts[n] for n in ("neck_roll_stage", "neck_roll_bearing_front")]
    steps = copy.deepcopy(ROLL_STAGE)
    steps[1]["from"] = [[0, 0, 120]]     # down across the journal, past the yaw shaft's top
    report = _check(params, parts, steps)
    assert any("not pressed along its axis" in p.what or "collides" in p.what for p in report.problems)


def test_every_part_must_be_in_the_sequence(params, neck_parts):
    parts = [neck_parts[n] for n in ("neck_roll_stage", "neck_roll_bearing_front", "neck_pitch_front_lug")]
    with pytest.raises(sequence.SequenceError, match="neck_pitch_front_lug"):
        _check(params, parts, ROLL_STAGE)


def test_the_build_stops_naming_the_step_and_the_parts(params, neck_parts, tmp_path):
    parts = [neck_parts[n] for n in ("neck_pitch_stage", "neck_roll_stage", "neck_pitch_front_lug",
                                     "neck_roll_bearing_front")]
    broken = {"drivers": {"hex-2": {"blade": 2.4, "length": 75, "handle": 25}},
              "screw_drivers": {"iso7380-M3": "hex-2"}, "subassemblies": {"roll": ROLL_STAGE},
              "sequence": [{"name": "stage", "parts": ["neck_pitch_stage"], "fixture": True},
                           {"name": "lug", "parts": ["neck_pitch_front_lug"], "from": [[30, 0, 0]],
                            "fits": ["neck_pitch_stage"]},
                           {"name": "roll stage", "subassembly": "roll", "from": [[60, 0, 0]]}]}
    path = tmp_path / "broken.yaml"
    path.write_text(yaml.safe_dump(broken))
    with pytest.raises(fab_build.BuildError) as caught:
        fab_build._assembly_sequence(tmp_path, Cache(tmp_path / "state.json"), Progress(), params,
                               Assembly(params, parts), "key", path)
    message = str(caught.value)
    assert "step 3 'roll stage'" in message and re.search(
        r"(neck_roll_stage|neck_roll_bearing_front) (touches|collides with) neck_pitch_front_lug", message), message
    assert (tmp_path / "reports" / "assembly.txt").exists()


def test_a_tight_ring_is_pressed_by_a_sleeve_on_that_ring(params, neck_parts):
    """The floating roll bearing's inner ring is the tight one (k6): pressed onto its journal by a sleeve on the inner
    ring, the lug then slides over its outer ring. The tool is checked clear and reported."""
    parts = [neck_parts[n] for n in ("neck_roll_stage", "neck_roll_bearing_front", "neck_pitch_front_lug")]
    steps = ROLL_STAGE + [{"name": "lug", "parts": ["neck_pitch_front_lug"], "from": [[30, 0, 0]],
                           "fits": ["neck_roll_bearing_front"]}]
    report = _check(params, parts, steps)
    assert report.ok, chk.format_report(report)
    [tool] = [t for s in report.steps for t in s.tools]
    assert tool["tool"] == "press sleeve for neck_roll_bearing_front on its inner ring" and tool["clearance_mm"] >= 0


def test_pressing_a_bearing_by_its_sliding_ring_is_caught(params, neck_parts):
    """The old seat: the 61800 pressed into the lug by its outer ring, while its inner ring is the tight one."""
    parts = [neck_parts[n] for n in ("neck_roll_stage", "neck_roll_bearing_front", "neck_pitch_front_lug")]
    steps = [{"name": "roll stage", "parts": ["neck_roll_stage"], "fixture": True},
             {"name": "lug", "parts": ["neck_pitch_front_lug"], "from": [[40, 0, 0]]},
             {"name": "bearing", "parts": ["neck_roll_bearing_front"], "from": [[20, 0, 0]],
              "fits": ["neck_pitch_front_lug", "neck_roll_stage"], "press": "outer"}]
    report = _check(params, parts, steps)
    [problem] = report.problems
    assert problem.step == "step 3 'bearing'"
    assert problem.what == ("neck_roll_bearing_front is pressed by its outer ring, but its tight ring is the inner (k6 on "
                            "neck_roll_stage): the press force would go through the balls")
    steps[2]["press"] = True       # a bearing's press must say which ring the tool bears on
    assert "say which ring the tool bears on" in _check(params, parts, steps).problems[0].what


def test_a_tight_ring_pushed_on_through_the_balls_is_caught(params, neck_parts):
    """The old order: the bearing in the front lug on the bench, then the lug slid over the journal, which forces the
    tight inner ring on through the balls."""
    parts = [neck_parts[n] for n in ("neck_roll_stage", "neck_roll_bearing_front", "neck_pitch_front_lug")]
    lug = [{"name": "lug", "parts": ["neck_pitch_front_lug"], "fixture": True},
           {"name": "bearing into the lug", "parts": ["neck_roll_bearing_front"], "from": [[20, 0, 0]],
            "fits": ["neck_pitch_front_lug"]}]
    steps = [{"name": "roll stage", "parts": ["neck_roll_stage"], "fixture": True},
             {"name": "lug over the journal", "subassembly": "lug", "from": [[30, 0, 0]], "fits": ["neck_roll_stage"]}]
    report = _check(params, parts, steps, {"lug": lug})
    [problem] = report.problems
    assert problem.step == "step 2 'lug over the journal'"
    assert problem.what.startswith("neck_roll_bearing_front's tight inner ring (k6 on neck_roll_stage) is pushed onto its "
                                   "seat by moving neck_roll_bearing_front onto it")


def test_a_journal_pushed_into_a_placed_tight_ring_is_caught(params):
    """The old tilt order: the left 626 in the left plate, then the tilt frame's journal pushed into its tight inner
    ring from the inside; the new one presses it onto the journal first and slides its outer ring into the bore."""
    frame = {p.name: p for p in head_frame.build(params) + eyes.build(params)}
    parts = [frame[n] for n in ("head_side_plate_left", "eyes_tilt_bearing_left", "eyes_tilt_frame")]
    old = [{"name": "plate", "parts": ["head_side_plate_left"], "fixture": True},
           {"name": "bearing", "parts": ["eyes_tilt_bearing_left"], "from": [[0, 20, 0]], "fits": ["head_side_plate_left"]},
           {"name": "tilt frame", "parts": ["eyes_tilt_frame"], "from": [[0, -150, 0]], "fits": ["eyes_tilt_bearing_left"]}]
    report = _check(params, parts, old)
    [problem] = report.problems
    assert problem.step == "step 3 'tilt frame'" and "moving eyes_tilt_frame into it" in problem.what
    new = [{"name": "plate", "parts": ["head_side_plate_left"], "fixture": True},
           {"name": "eyes", "subassembly": "eyes", "from": [[0, -150, 0]], "fits": ["head_side_plate_left"]}]
    eyes_sub = [{"name": "tilt frame", "parts": ["eyes_tilt_frame"], "fixture": True},
                {"name": "bearing", "parts": ["eyes_tilt_bearing_left"], "from": [[0, 30, 0]], "fits": ["eyes_tilt_frame"],
                 "press": "inner"}]
    report = _check(params, parts, new, {"eyes": eyes_sub})
    assert report.ok, chk.format_report(report)


def _eye_check(params):
    parts = {p.name: p for p in eyes.build(params)}
    chosen = [parts[n] for n in ("left_eye_cup", "left_eye_hub", "left_eye_hub_set_screw_0",
                                 "left_eye_hub_set_screw_1")]
    steps = [{"name": "cup", "parts": ["left_eye_cup"], "fixture": True},
             {"name": "hub", "parts": ["left_eye_hub"], "from": [[0, 0, -30]], "fits": ["left_eye_cup"]},
             {"name": "set screws", "fasteners": ["left_eye_hub_set_screw_*"]}]
    data = {"drivers": {"hex-0.9": {"blade": 1.0, "length": 50, "handle": 15}},
            "screw_drivers": {"iso4029-M2": "hex-0.9"}, "subassemblies": {}, "sequence": steps}
    seq = sequence.parse(data, Path("variant.yaml"), [p.name for p in chosen])
    return chk.check(params, Assembly(params, chosen), seq)


def test_a_set_screw_is_turned_from_its_socket_through_the_cups_access_hole(params):
    """A headless set screw: the key enters at its socket, the screw's own diameter, and must get out through the
    eye cup's access hole; a hole narrower than the screw stops it."""
    report = _eye_check(params)
    assert report.ok, chk.format_report(report)
    data = copy.deepcopy(params.root._data)
    data["geometry"]["eyes"]["hub"]["access_diameter"] = 1.5
    narrow = parse(data, "variant", params.path)
    report = _eye_check(narrow)
    assert report.problems and report.problems[0].step == "step 3 'set screws'"
    assert re.match(r"left_eye_hub_set_screw_0 \(hex-0.9\): the 2 mm tool along the axis hits left_eye_cup",
                    report.problems[0].what), report.problems[0].what


def test_the_check_leaves_the_parts_unmeshed(params):
    """It meshes copies: a mesh left on a part's faces (the placed shapes share them) changes what BoundingBox()
    gives every later step of the build, which would then depend on whether this step ran or was cached."""
    plate = Part("plate", "plate", "neck_base", "machined", geom.cyl("z", 40, 0, 5), loc(), material="aluminium-6082")
    ball = Part("ball", "ball", "neck_base", "machined", geom.sphere(7), loc(0, 0, 12), material="aluminium-6082")
    before = [p.shape.BoundingBox() for p in (plate, ball)]
    steps = [{"name": "plate", "parts": ["plate"], "fixture": True},
             {"name": "ball", "parts": ["ball"], "from": [[0, 0, 40]]}]
    assert _check(params, [plate, ball], steps).ok
    after = [p.shape.BoundingBox() for p in (plate, ball)]
    assert [(b.xmin, b.xmax, b.zmin, b.zmax) for b in after] == [(b.xmin, b.xmax, b.zmin, b.zmax) for b in before]


def test_a_mesh_left_on_the_parts_does_not_change_the_result(params):
    """A part meshed earlier in the build (its STL, the assembly's GLB) is checked as one never meshed: the check meshes
    copies at its own deflection and bounds the parts by their geometry. A ball lowered beside a post."""
    def run(premeshed):
        def part(name, shape, at):
            return Part(name, name, "neck_base", "machined", shape, at, material="aluminium-6082")
        plate = part("plate", geom.cyl("z", 60, 0, 5), loc())
        post = part("post", geom.cyl("z", 20, 5, 30), loc(18.5))
        ball = part("ball", geom.sphere(7), loc(0, 0, 20))
        for p in (plate, post, ball) if premeshed else ():
            BRepMesh_IncrementalMesh(p.local.wrapped, 0.01, False, 0.1, True).Perform()
        steps = [{"name": "plate", "parts": ["plate"], "fixture": True},
                 {"name": "post", "parts": ["post"], "from": [[0, 0, 40]]},
                 {"name": "ball", "parts": ["ball"], "from": [[0, 0, 40]]}]
        report = _check(params, [plate, post, ball], steps)
        assert report.ok, chk.format_report(report)
        return [(s.label, s.samples, s.closest, s.closest_to) for s in report.steps]
    fresh = run(False)
    assert fresh[2][3] == "ball x post" and 1.0 < fresh[2][2] < 1.5     # 1.5 mm apart, less the meshes' allowance
    assert run(True) == fresh


def _meshed_faces(shape) -> int:
    from OCP.BRep import BRep_Tool
    from OCP.TopLoc import TopLoc_Location
    return sum(BRep_Tool.Triangulation_s(f.wrapped, TopLoc_Location()) is not None for f in shape.Faces())


def test_exact_distances_are_measured_on_meshed_copies(params):
    """OpenCASCADE's exact distance bounds a face by its triangles where it has them and by its surface's control
    points where not: on a part whose STL came from the cache (never meshed in this build) one step took minutes
    instead of seconds. The check measures meshed copies, and leaves the parts as they were."""
    ball = Part("ball", "ball", "neck_base", "machined", geom.sphere(7), loc(0, 0, 12), material="aluminium-6082")
    world = chk._World(Assembly(params, [ball]))
    measured = world.shape("ball")
    assert _meshed_faces(measured) == len(measured.Faces()) > 0
    assert _meshed_faces(ball.shape) == 0 and _meshed_faces(world.placed["ball"].shape) == 0
    assert _meshed_faces(world.shape("ball", np.array([0.0, 0, 5]))) == len(measured.Faces())
