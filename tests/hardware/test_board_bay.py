# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The board bay with the harness plugged in: a mated plug and its wires' turn on every header a cable ends in
(JST VH included, whose header KiCad's STEP does not model), each clear of the board above, the standoffs and the
plate; the old stack (12 mm standoffs in a 46 mm bay) fails, in the board-bay check and in the interference check."""
import pytest
import yaml

from robogene_head.assembly import Assembly
from robogene_head.checks import board_bay, interference
from robogene_head.geom import exact_bounds
from robogene_head.harness import pinout, spec
from robogene_head.parts import board_plugs, build_all
from robogene_head_model.params import ParameterError, load


def _bay(params, external):
    parts = [p for p in build_all(params, external) if p.link == "neck_base"]
    plugs = board_plugs.build(params, external.board)
    return parts, plugs, board_bay.check(params, parts, plugs)


def _variant(params, tmp_path, name, change):
    data = yaml.safe_load(params.path.read_text())
    change(data)
    path = tmp_path / f"{name}.yaml"
    path.write_text(yaml.safe_dump(data))
    return load(path)


def _old_stack(data):
    """The stack as it was: 12 mm standoffs between the boards in a 46 mm bay."""
    data["purchased"]["standoff-M3x12-MF"] = dict(data["purchased"]["standoff-M3x30-MF"], length=12)
    data["purchased"]["standoff-M3x96-FF"]["length"] = 46   # the base's standoffs, by the key neck.py uses
    data["boards"]["standoffs"]["between"] = "standoff-M3x12-MF"
    data["boards"]["stack_pitch"] = 13.6
    data["boards"]["origin"] = [0, 0, -48]
    data["geometry"]["neck_base"]["bay_height"] = 46


def test_every_cable_end_on_a_board_has_its_mated_plug(params, external):
    _, plugs, _ = _bay(params, external)
    ends = set()
    for cable in spec.load(params).cables:
        ends.add((cable.board, cable.ref))
        if isinstance(cable.to, tuple):
            ends.add(tuple(cable.to))
    assert {(p.board, p.ref) for p in plugs} == ends
    vh = [p for p in plugs if p.mpn.startswith("B2P-VH")]
    assert len(vh) == 11 and {p.housing for p in vh} == {"jst-VHR-2N"}   # 3 boards x J20, J30, J1; J5 on two


def test_the_plugs_stand_where_the_datasheets_put_them(params, external):
    """Housing top: the PCB's top face plus the mated height; the wires' turn: wire_bend_factor ods and half an od
    above it; a PH plug stands on its header's model, a VH one (no model) on the PCB with the header's tails below."""
    _, plugs, _ = _bay(params, external)
    node = params.root.node("boards")
    thickness, factor = node.num("thickness"), node.node("plugs").num("wire_bend_factor")
    connectors = pinout.connectors()
    low = external.board.z_range[0]
    for plug in plugs:
        mated = node.node("plugs").node("mated_height").num(plug.mpn)
        assert plug.housing_top == pytest.approx(thickness + mated)
        assert plug.wire_top == pytest.approx(plug.housing_top + plug.wire_od * (factor + 0.5))
        lo, hi = exact_bounds(plug.part.local)
        x0, x1, y0, y1 = connectors[plug.ref].body
        assert lo[0] == pytest.approx(x0, abs=1e-3) and hi[1] == pytest.approx(y1, abs=1e-3)
        assert hi[2] == pytest.approx(plug.wire_top, abs=1e-3)
        if plug.mpn.startswith("B2P-VH"):
            assert plug.base == thickness and lo[2] == pytest.approx(low, abs=1e-3) and low < -1
            assert plug.wire_od == 2.0 if plug.ref in ("J1", "J5") else plug.wire_od == 1.4   # power 18, motor 22 AWG
        else:
            assert 7.5 < plug.base < plug.housing_top    # on the PH header's model, 6 mm above the PCB
            assert plug.wire_od == 0.9


def test_every_mated_plug_has_room_in_the_bay(params, external):
    _, plugs, report = _bay(params, external)
    assert report.ok, board_bay.format_report(report)
    # one plug per board end of every cable: 26, and the two brake cables of board revision D
    assert len(report.rows) == len(plugs) == _board_ends(params) == 28
    # the top board's power plug is the nearest to the base plate, and still the wanted clearance from it
    top = next(r for r in report.rows if r.plug.part.name == "plug_eyes-pan_J1")
    assert top.nearest == "neck_base_plate" and report.minimum <= top.distance < 3


def test_the_old_spacing_is_caught(params, external, tmp_path):
    old = _variant(params, tmp_path, "old-stack", _old_stack)
    _, plugs, report = _bay(old, external)
    text = board_bay.format_report(report)
    assert not report.ok
    rows = {r.plug.part.name: r for r in report.rows}
    # a PH plug's wires reach into the header pins of the board above; a VH plug through the board above, where
    # the VH plug of that board stands
    assert rows["plug_neck-pitch-roll_J21"].nearest == "board_neck-yaw-eyes-tilt", text
    assert rows["plug_neck-pitch-roll_J21"].distance == 0, text
    for name in ("plug_neck-pitch-roll_J20", "plug_neck-yaw-eyes-tilt_J1"):
        assert rows[name].distance == 0, text
    assert rows["plug_eyes-pan_J1"].nearest == "neck_base_plate" and rows["plug_eyes-pan_J1"].distance == 0, text
    assert "plugs without room" in text.splitlines()[-1]


@pytest.mark.timeout(600)
def test_the_interference_check_sees_the_plugs(params, external, tmp_path):
    """The same old stack in the interference check, with plugs as fab.py adds them to the sweep: a VH plug of the
    bottom board overlaps the middle board, the top board's supply plug the base plate; without the plugs the same
    parts pass. (A few parts only: a plug against a whole board compound is a slow boolean.)"""
    old = _variant(params, tmp_path, "old-stack", _old_stack)
    parts, plugs, _ = _bay(old, external)
    keep = {"board_neck-yaw-eyes-tilt", "neck_base_plate"}
    base = [p for p in parts if p.name in keep]
    bare = interference.check(old, Assembly(old, base), [{}])
    assert bare.ok, interference.format_report(bare, bare.minimum)
    chosen = [q.part for q in plugs if q.part.name in ("plug_neck-pitch-roll_J20", "plug_eyes-pan_J1")]
    report = interference.check(old, Assembly(old, base + chosen), [{}])
    pairs = {tuple(sorted((r.a, r.b))) for r in report.interferences}
    assert pairs == {("board_neck-yaw-eyes-tilt", "plug_neck-pitch-roll_J20"), ("neck_base_plate", "plug_eyes-pan_J1")}
    # fab.py leaves those pairs, on one link, to the board-bay check (the slow booleans of the sweep's first pose):
    # the sweep then measures the plugs only against parts that move relative to them
    handed_over = interference.check(old, Assembly(old, base + chosen), [{}],
                                     static_checked_elsewhere=frozenset(p.name for p in chosen))
    assert not handed_over.interferences and handed_over.pairs_checked < report.pairs_checked


def test_the_plugs_do_not_depend_on_a_mesh_of_the_board(params, external):
    """The interference check's cache keys on the plugs' shapes: a board meshed earlier in the build (the GLB
    export) must give the same plugs (the VH tails once took their depth from the mesh)."""
    from robogene_head import board_model
    from robogene_head.export import shape_hash
    board = board_model._read(external.board.path, external.board.sha256)   # a copy of our own to mesh
    before = [shape_hash(q.part.local) for q in board_plugs.build(params, board)]
    for solid in board.solids:
        solid.tessellate(0.5, 0.5)
    assert [shape_hash(q.part.local) for q in board_plugs.build(params, board)] == before


def test_a_header_without_a_mated_height_is_named(params, external, tmp_path):
    def drop(data):
        del data["boards"]["plugs"]["mated_height"]["B2P-VH(LF)(SN)"]
    with pytest.raises(ParameterError, match=r"boards\.plugs\.mated_height: no entry for B2P-VH\(LF\)\(SN\) \(J1, "
                                             r"cable power-host\)"):
        board_plugs.build(_variant(params, tmp_path, "no-vh", drop), external.board)


def test_a_mated_height_inside_the_header_is_named(params, external, tmp_path):
    def low(data):
        data["boards"]["plugs"]["mated_height"]["B4B-PH-K-S(LF)(SN)"] = 4
    with pytest.raises(ParameterError, match=r"mated_height\.B4B-PH-K-S\(LF\)\(SN\): 4 mm above the PCB leaves the "
                                             r"plug inside J21's header"):
        board_plugs.build(_variant(params, tmp_path, "low-ph", low), external.board)


def _board_ends(params):
    """Cable ends on a board header: every cable's source, and the far end of a board-to-board cable."""
    return sum(1 + isinstance(c.to, tuple) for c in spec.load(params).cables)


def test_the_package_reports_the_bay(fab, params):
    text = (fab / "reports" / "board-bay.txt").read_text()
    assert text.startswith(f"board bay: {_board_ends(params)} mated plugs")
    assert text.rstrip().endswith("board bay: ok")
    assert "plug_eyes-pan_J1" in text and "jst-VHR-2N" in text
