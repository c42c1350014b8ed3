# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The wiring harness: the span model measures bend radius and twist correctly on curves of known shape; the head's
routes pass, and the check fails on a variant over its bend radius or twist limit; lengths come from the sweep;
the pinout is the board's; WireViz draws it; the package carries it and its parts reach the BOM."""
import csv
import dataclasses
import html
import json
import math

import numpy as np
import pytest
import yaml

from robogene_head_model import params as params_mod
from robogene_head.harness import build as harness_build, drawing, picture, pinout, plan, spans, spec
from robogene_head.parts import eyes, head_frame, joint_encoders, neck

from param_variants import edited


@pytest.fixture(scope="module")
def parts(params):
    """The parts the harness reaches (drives, encoders, cameras): no board STEP needed."""
    return neck.build(params) + head_frame.build(params) + eyes.build(params) + joint_encoders.build(params)


def _frame(at, d, up):
    return spans.Frame(np.array(at, float), np.array(d, float) / np.linalg.norm(d), np.array(up, float) / np.linalg.norm(up))


def test_a_straight_span_is_straight_and_untwisted():
    s = spans.shape(_frame([0, 0, 0], [0, 0, 1], [1, 0, 0]), _frame([0, 0, 100], [0, 0, 1], [1, 0, 0]), 100.0)
    assert s.length == pytest.approx(100.0, rel=1e-3) and s.min_radius > 1e4 and abs(s.twist_deg) < 1e-6


def test_twist_between_the_clamps_is_measured():
    s = spans.shape(_frame([0, 0, 0], [0, 0, 1], [1, 0, 0]), _frame([0, 0, 100], [0, 0, 1], [0, 1, 0]), 100.0)
    assert s.twist_deg == pytest.approx(90.0, abs=0.5)


def test_a_u_loop_of_a_half_circles_length_is_the_half_circle():
    """Two legs 40 mm apart joined by a cable of a half circle's length: the least bending shape through those ends is
    the half circle, R 20 all along. A flat cable whose face turns with the loop (normal in the loop's plane) bends
    out of its plane only; one lying in the loop's plane (normal across it) bends within its plane."""
    across = spans.shape(_frame([0, 0, 0], [1, 0, 0], [0, 0, 1]), _frame([0, 0, 40], [-1, 0, 0], [0, 0, -1]), math.pi * 20)
    assert across.length == pytest.approx(math.pi * 20, rel=1e-3)
    assert across.min_radius == pytest.approx(20, rel=1e-3)
    assert across.min_inplane_radius > 1e4 and abs(across.twist_deg) < 0.5
    within = spans.shape(_frame([0, 0, 0], [1, 0, 0], [0, 1, 0]), _frame([0, 0, 40], [-1, 0, 0], [0, 1, 0]), math.pi * 20)
    assert within.min_inplane_radius == pytest.approx(within.min_radius, rel=1e-6)


def test_a_longer_loop_keeps_its_bend_in_the_loop():
    """Legs 30 mm apart with 120 mm of cable: the extra length runs out along the legs and the loop stays near a half
    circle on them (R 15), instead of the tight apex a curve of fixed form (the cubic through the same ends, which
    read R 4.6 here) would put there."""
    s = spans.shape(_frame([0, 0, 0], [1, 0, 0], [0, 1, 0]), _frame([0, 0, 30], [-1, 0, 0], [0, 1, 0]), 120.0)
    assert 15 <= s.min_radius < 17


def test_the_modelled_cable_runs_from_clamp_to_clamp_at_its_length_and_bends_least():
    a, b = _frame([0, 0, 0], [0, 0, 1], [1, 0, 0]), _frame([35, 10, 60], [1, 0, 0], [0, 0, -1])
    c = spans.curve(a, b, 110.0)
    assert np.allclose(c.points[0], a.at) and np.linalg.norm(c.points[-1] - b.at) < 0.01
    assert np.linalg.norm(np.diff(c.points, axis=0), axis=1).sum() == pytest.approx(110.0)
    # Its bending energy is below the first guess's it was relaxed from (the cubic of the same length).
    guess = spans._first_guess(a, b, 110.0, spans.SEGMENTS)[None]
    ends = spans._directions([a]), spans._directions([b])
    assert spans._energy(*ends, c.directions[None])[0] < 0.9 * spans._energy(*ends, guess)[0]
    # The same span gives the same curve, bit for bit: the build's reports are byte-identical run to run.
    again = spans.curve(a, b, 110.0)
    assert np.array_equal(again.points, c.points) and np.array_equal(again.normals, c.normals)


def test_a_span_shorter_than_its_clamps_apart_is_refused():
    with pytest.raises(ValueError, match="cannot reach"):
        spans.shape(_frame([0, 0, 0], [0, 0, 1], [1, 0, 0]), _frame([0, 0, 100], [0, 0, 1], [1, 0, 0]), 90.0)
    # Over a sweep, the refusal names the pose it happens at (here the second of three).
    near, far = _frame([0, 0, 0], [0, 0, 1], [1, 0, 0]), _frame([0, 0, 100], [0, 0, 1], [1, 0, 0])
    with pytest.raises(spans.SpanError, match="cannot reach") as refused:
        spans.curves([near, near, near], [_frame([0, 0, 50], [0, 0, 1], [1, 0, 0]), far, far], 90.0)
    assert refused.value.pose == 1


def test_the_heads_routes_pass(params, parts):
    h = plan.plan(params, spec.load(params), parts)
    assert h.ok, h.problems
    crossed = {j for s in h.spans.values() for j in s.joints}
    assert crossed == set(params_mod.CHAIN_JOINTS)   # every joint has a route across it
    for s in h.spans.values():
        assert s.checks and all(c.min_radius >= c.allowed_radius for c in s.checks)


def test_a_cable_over_its_bend_radius_fails_the_check(params, parts, tmp_path):
    def thicker(data):
        data["harness"]["classes"]["motor-22awg"]["wire_od"] = 2.5   # R 25 > the neck loops' tightest bends
    h = plan.plan(edited(tmp_path, thicker), spec.load(edited(tmp_path, thicker)), parts)
    assert not h.ok
    assert any("motor-22awg x2 bends to R" in p and "its minimum is R 25.0 mm" in p for p in h.problems), h.problems


def test_a_twisted_group_is_held_to_its_group_diameter(params, parts, tmp_path):
    def twisted(data):
        data["harness"]["classes"]["motor-22awg"]["laid"] = "twisted"   # pair od 2.8 mm: R 28
    p2 = edited(tmp_path, twisted)
    h = plan.plan(p2, spec.load(p2), parts)
    assert any("motor-22awg x2" in p and "R 28.0 mm (10 x 2.80 mm)" in p for p in h.problems), h.problems


def test_a_twist_over_its_limit_fails_the_check(params, parts, tmp_path):
    def stiff(data):
        data["harness"]["classes"]["signal-28awg"]["twist_deg_per_m"] = 100   # roll twists its loop ~135 deg/m
    p2 = edited(tmp_path, stiff)
    h = plan.plan(p2, spec.load(p2), parts)
    assert any("span roll_cross -> roll_land" in p and "signal-28awg twists" in p and "limit is 100 deg/m" in p
               for p in h.problems), h.problems


def test_a_flat_cable_bent_in_its_own_plane_fails(params, parts, tmp_path):
    def turned(data):   # lay the camera cable flat across the pan loop: panning now bends it within its plane
        for side in ("eye_l", "eye_r"):
            data["harness"]["clamps"][side]["up"] = [0, 0, 1]
        for side in ("pan_feed_l", "pan_feed_r"):
            data["harness"]["clamps"][side]["up"] = [0, 0, 1]
    p2 = edited(tmp_path, turned)
    h = plan.plan(p2, spec.load(p2), parts)
    assert any("camera-ffc bends in its own plane" in p for p in h.problems), h.problems


def test_free_lengths_come_from_the_sweep(params, parts, tmp_path):
    s = spec.load(params)
    h = plan.plan(params, s, parts)
    yaw_span = h.spans[("yaw_cross", "head_entry")]
    assert yaw_span.joints == ("neck_yaw",) and yaw_span.poses == s.sweep_samples
    assert yaw_span.length == math.ceil(yaw_span.max_chord * (1 + s.free_slack) / 5) * 5

    # The longest chord is the clamps' greatest distance over the sampled poses, recomputed here from the kinematics.
    from robogene_head import kinematics
    a, b = s.clamps["yaw_cross"], s.clamps["head_entry"]
    chords = []
    for value in np.linspace(params.joints["neck_yaw"].lower, params.joints["neck_yaw"].upper, s.sweep_samples):
        poses = kinematics.link_poses(params, {"neck_yaw": value})
        pa = poses[a.link][:3, :3] @ a.at + poses[a.link][:3, 3]
        pb = poses[b.link][:3, :3] @ b.at + poses[b.link][:3, 3]
        chords.append(np.linalg.norm(pb - pa))
    assert yaw_span.max_chord == pytest.approx(max(chords), abs=1e-9) and max(chords) > min(chords) + 5

    def narrow(data):   # yaw held still: its span is cut to its rest chord
        data["joints"]["neck_yaw"]["min"], data["joints"]["neck_yaw"]["max"] = -0.5, 0.5
        data["control_joints"][2]["min"], data["control_joints"][2]["max"] = -0.5, 0.5
    p2 = edited(tmp_path, narrow)
    h2 = plan.plan(p2, spec.load(p2), parts)
    assert h2.spans[("yaw_cross", "head_entry")].max_chord < yaw_span.max_chord - 4
    assert h2.spans[("yaw_cross", "head_entry")].length < yaw_span.length
    # every cable across yaw follows, though a 5 mm shorter span can vanish in a cable's rounding to 10 mm
    cut = {c.name: c.length for c in h.cables}
    across = [c for c in h2.cables if "head_entry" in c.via]
    assert all(c.length <= cut[c.name] for c in across) and any(c.length < cut[c.name] for c in across)
    # Each cable: service loops at both ends, the free spans it crosses, the laid runs: at least the spans.
    for c in h.cables:
        free = sum(sp.length for key, sp in h.spans.items() if c.name in sp.cables)
        assert c.length >= free + 2 * s.service_loop


def test_pinout_is_the_boards(params):
    conns = pinout.connectors()
    assert conns["J21"].nets == ("+5V", "M1_ENC_A", "M1_ENC_B", "GND") and conns["J21"].mpn == "B4B-PH-K-S(LF)(SN)"
    assert conns["J1"].nets == ("VIN_RAW", "GND") and conns["J1"].mpn == "B2P-VH(LF)(SN)"
    # pin 1 of the supply header, from the KiCad PCB (105, 117), in the board STEP's frame (centre 145, 130; y up)
    assert conns["J1"].at == (-40.0, 13.0)


def test_bad_harness_entries_are_named(params, parts, tmp_path):
    def unknown_clamp(data):
        data["harness"]["cables"][3]["via"] = ["bay_exit", "nowhere"]
    with pytest.raises(params_mod.ParameterError, match=r"harness\.cables\[3\]\.via: 'nowhere' is not a clamp"):
        spec.load(edited(tmp_path, unknown_clamp))

    def no_route(data):
        data["harness"]["cables"][3]["via"] = ["bay_exit"]   # roll motor: its part is on the pitch stage
    p2 = edited(tmp_path, no_route)
    with pytest.raises(params_mod.ParameterError, match=r"harness\.cables\[3\] \(roll-motor\): the route ends on "
                                                         r"neck_base but its far end is on neck_pitch_link"):
        plan.plan(p2, spec.load(p2), parts)

    def no_connector(data):
        data["harness"]["cables"][0]["from"] = ["neck-pitch-roll", "J99"]
    p3 = edited(tmp_path, no_connector)
    with pytest.raises(params_mod.ParameterError, match=r"harness\.cables\[0\] \(pitch-motor\)\.from: the board has "
                                                         r"no connector J99"):
        plan.plan(p3, spec.load(p3), parts)


def test_camera_cable_lengths_are_keyed_by_catalog_part(params, tmp_path):
    """Keyed by name as every mapping of the parameter file (the board-config codegen reads the same file and refuses
    number keys); the old layout, length -> part, is refused naming the field."""
    assert spec.load(params).camera_lengths == {200.0: "rpi-camera-cable-200", 300.0: "rpi-camera-cable-300",
                                                500.0: "rpi-camera-cable-500"}

    def number_keys(data):
        data["harness"]["camera_cables"]["lengths"] = {200: "rpi-camera-cable-200"}
    with pytest.raises(params_mod.ParameterError, match=r"harness\.camera_cables\.lengths: expected a mapping of "
                                                         r"catalog keys to their positive lengths \(mm\)"):
        spec.load(edited(tmp_path, number_keys))


def test_wireviz_draws_every_cable(params, parts, tmp_path):
    from robogene_bom import catalog
    s = dataclasses.replace(spec.load(params), sweep_samples=3)
    h = plan.plan(params, s, parts)
    files = drawing.write(h, catalog.load(), tmp_path)
    boards = params.root.node("boards").raw("names")
    for stem in [f"harness-{b}" for b in boards] + ["harness-cameras"]:
        svg = (tmp_path / f"{stem}.svg").read_text()
        assert svg.startswith("<?xml") and "</svg>" in svg
    svg = html.unescape((tmp_path / "harness-neck-pitch-roll.svg").read_text())   # Graphviz writes '-' as &#45;
    assert "PHR-6" in svg and "VHR-2N" in svg and "pitch-motor" in svg and "M1_ENC_A" in svg
    tsv = (tmp_path / "harness-neck-pitch-roll.bom.tsv").read_text()
    assert "SPH-002T-P0.5S" in tsv and "SVH-21T-P1.1" in tsv
    assert all(p.is_file() for p in files)


def test_the_build_stops_on_a_violation(params, parts, tmp_path):
    from robogene_bom import catalog
    from robogene_head.cache import Cache
    from robogene_head.progress import Progress

    def thicker(data):
        data["harness"]["classes"]["signal-28awg"]["bend_factor"] = 40
    p2 = edited(tmp_path, thicker)
    with pytest.raises(harness_build.HarnessError, match=r"(?s)harness check failed.*signal-28awg x\d bends to R"):
        harness_build.build(p2, parts, tmp_path / "fab", Cache(tmp_path / "state.json"), catalog.load(),
                            Progress(open("/dev/null", "w")), "geometry")
    assert "FAILED" in (tmp_path / "fab" / "reports" / "harness.txt").read_text()


def test_the_build_stops_on_a_span_through_a_part(params, parts, tmp_path):
    """The route the head's wires took before (one loop from the bay across pitch, roll and yaw to a tie under the
    floor beside the yaw axis) passes through the roll drive: the parts in its way stop the build, named."""
    from robogene_bom import catalog
    from robogene_head.cache import Cache
    from robogene_head.progress import Progress

    def unnamed(data):
        h = data["harness"]
        h["clamps"]["head_entry"] = {"link": "head_frame", "at": [-10, 0, -5], "dir": [1, 0, 0], "up": [0, 0, -1]}
        for c in h["cables"]:
            if "roll_land" in c.get("via", []):
                c["via"] = ["bay_exit", "head_entry"] + c["via"][6:]
    with pytest.raises(harness_build.HarnessError,
                       match=r"(?s)harness check failed.*span bay_exit -> head_entry: the round wires \(bundle .* mm\) "
                             r"pass through neck_roll_gearhead \(neck_pitch_link\)"):
        harness_build.build(edited(tmp_path, unnamed), parts, tmp_path / "fab", Cache(tmp_path / "state.json"),
                            catalog.load(), Progress(open("/dev/null", "w")), "geometry")
    assert "NOT MET (the build stops)" in (tmp_path / "fab" / "reports" / "harness.txt").read_text()


def test_package_holds_the_harness(fab, params):
    data = json.loads((fab / "harness" / "harness.json").read_text())
    assert data["ok"] and not data["problems"]
    boards = params.root.node("boards").raw("names")
    for stem in [f"harness-{b}" for b in boards] + ["harness-cameras"]:
        for ext in ("yml", "svg", "png", "html", "bom.tsv"):
            assert (fab / "harness" / f"{stem}.{ext}").stat().st_size > 0
    assert "OK: every span" in (fab / "reports" / "harness.txt").read_text()
    assert (fab / "harness" / "harness-eyes.png").stat().st_size > 0
    rows = {r["key"]: r for r in csv.DictReader((fab / "bom" / "robogene-head-bom.csv").open())}
    # Housings: one per crimped end; contacts: one per wire end; wire by the metre.
    expected = {}
    for line in data["bom"]:
        expected[line["key"]] = expected.get(line["key"], 0) + line["per_head"]
    for key, qty in expected.items():
        assert float(rows[key]["qty_per_head"]) == pytest.approx(qty, abs=0.006), key
    ends = [c for c in data["cables"] if c["header"] == "B4B-PH-K-S(LF)(SN)"]
    assert expected["jst-PHR-4"] == len(ends) and rows["wire-28awg-ptfe"]["unit"] == "m"
    assert expected["rpi-camera-cable-300"] == 2 and "rpi-camera-cable-500" not in expected
    for key in ("meanwell-GST90A12-P1M", "canable-2.0", "raspberrypi-SC1112"):
        assert rows[key]["qty_per_head"] == "1"
    assert rows["pcb-assembly-motor-board"]["qty_per_head"] == str(int(params.root.node("boards").num("count")))


def test_the_harness_is_rebuilt_when_the_catalog_changes(params, parts, tmp_path):
    """The drawings name the housings and crimps by their catalog MPN: a changed catalog redraws them, and only them
    (two full builds, not three: the test ran over its time limit on a loaded machine); a changed geometry
    re-measures the spans' clearance."""
    from robogene_bom import catalog
    from robogene_head.cache import Cache
    from robogene_head.progress import Progress
    import io
    cache, out = Cache(tmp_path / "state.json"), tmp_path / "fab"
    log = io.StringIO()
    harness_build.build(params, parts, out, cache, catalog.load(), Progress(log), "geometry")
    harness_build.build(params, parts, out, cache, catalog.load(), Progress(log), "geometry")
    assert log.getvalue().count("harness: unchanged") == 1
    data = yaml.safe_load(catalog.DEFAULT_PATH.read_text())
    data["parts"]["jst-PHR-4"]["mpn"] = "PHR-4-OTHER"
    changed = tmp_path / "catalog.yaml"
    changed.write_text(yaml.safe_dump(data))
    report_before = (out / "reports" / "harness.txt").read_text()
    harness_build.build(params, parts, out, cache, catalog.load(changed), Progress(log), "geometry")
    assert log.getvalue().count("harness: unchanged") == 1
    assert "PHR-4-OTHER" in html.unescape((out / "harness" / "harness-neck-pitch-roll.svg").read_text())
    # only the drawings: the spans are not swept again for a catalog, and the checks' report stands
    assert log.getvalue().count("harness: sweeping") == 1
    assert log.getvalue().count("checks unchanged; WireViz drawings for the changed catalog") == 1
    assert (out / "reports" / "harness.txt").read_text() == report_before
    assert all((out / "harness" / f"{pic.name}.png").exists() for pic in picture.PICTURES)
    # The spans' clearance depends on every part's shape: a changed geometry digest measures it again.
    harness_build.build(params, parts, out, cache, catalog.load(changed), Progress(log), "geometry, a part moved")
    assert log.getvalue().count("harness: unchanged") == 1
    assert log.getvalue().count("harness: sweeping") == 2


def test_every_brake_has_its_cable(params, parts):
    """Board revision D switches each brake's coil on a 2-pin header (+12V, the channel's switched return); the
    harness carries a cable from it to the brake for each braked joint, with PH housings and crimps."""
    h = plan.plan(params, spec.load(params), parts)
    assert not plan.brake_wiring_problems(params, h.cables)
    brakes = {r.target: r for r in h.cables if r.target.endswith("_brake")}
    assert set(brakes) == {"neck_pitch_brake", "neck_roll_brake"}
    assert brakes["neck_pitch_brake"].source == ("neck-pitch-roll", "J23")
    assert brakes["neck_pitch_brake"].wires == ("+12V", "M1_BRAKE_N")
    assert brakes["neck_roll_brake"].source == ("neck-pitch-roll", "J33")
    assert brakes["neck_roll_brake"].wires == ("+12V", "M2_BRAKE_N")
    lines = [line for line in plan.bom_lines(h) if line[2] in ("harness pitch-brake", "harness roll-brake")]
    assert sorted(k for k, _, _ in lines if k.startswith("jst-")) == \
        ["jst-PHR-2", "jst-PHR-2", "jst-SPH-002T-P0.5S", "jst-SPH-002T-P0.5S"]


def test_a_brake_without_its_cable_fails(params, parts, tmp_path):
    def drop_roll_brake(data):
        data["harness"]["cables"] = [c for c in data["harness"]["cables"] if c["name"] != "roll-brake"]
    broken = edited(tmp_path, drop_roll_brake)
    h = plan.plan(broken, spec.load(broken), parts)
    assert any(p.startswith("neck_roll: its brake spec-brake-23-12V-8mNm has no cable") for p in h.problems), h.problems


def test_a_brake_cable_from_the_wrong_header_fails(params, parts, tmp_path):
    def swap(data):
        for c in data["harness"]["cables"]:
            if c["name"] == "roll-brake":
                c["from"] = ["neck-pitch-roll", "J23"]
    broken = edited(tmp_path, swap)
    h = plan.plan(broken, spec.load(broken), parts)
    assert any("roll-brake: neck_roll_brake needs neck-pitch-roll's header with +12V, M2_BRAKE_N" in p
               for p in h.problems), h.problems
