# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The assembly places KiCad's board STEP once per motor-control board, in the neck base's board bay: the
geometry matches the STEP read back here with OpenCASCADE's own reader, the boards join the interference
check and the mass properties, and a missing or wrong STEP stops the build with a message naming it."""
import json
import subprocess
import sys

import cadquery as cq
import numpy as np
import pytest
import yaml
from OCP.Bnd import Bnd_Box
from OCP.BRepBndLib import BRepBndLib
from OCP.BRepGProp import BRepGProp
from OCP.GProp import GProp_GProps
from OCP.IFSelect import IFSelect_RetDone
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_SOLID
from OCP.TopExp import TopExp_Explorer

from robogene_head import board_model, external as ext, massprops
from robogene_head.assembly import Assembly
from robogene_head.checks import interference
from robogene_head.fab import design_hash
from robogene_head_model.params import ParameterError, load
from robogene_head.parts import build_all

from conftest import REPO


def _read_step(path):
    reader = STEPControl_Reader()
    assert reader.ReadFile(str(path)) == IFSelect_RetDone
    reader.TransferRoots()
    return reader.OneShape()


def _solids(shape):
    out, explorer = [], TopExp_Explorer(shape, TopAbs_SOLID)
    while explorer.More():
        out.append(explorer.Current())
        explorer.Next()
    return out


def _volume(shape):
    props = GProp_GProps()
    BRepGProp.VolumeProperties_s(shape, props)
    return props.Mass()


def _bounds(shape):
    box = Bnd_Box()
    BRepBndLib.AddOptimal_s(shape, box, False, False)
    return np.array(box.Get())   # xmin, ymin, zmin, xmax, ymax, zmax


def _boards(assembly):
    return [p for p in assembly.parts if p.kind == "board"]


def test_three_boards_match_the_kicad_step(params, assembly, board_step):
    node = params.root.node("boards")
    boards = _boards(assembly)
    assert [p.name for p in boards] == [f"board_{n}" for n in node.raw("names")]
    assert len(boards) == int(node.num("count")) == 3
    step = _read_step(board_step)
    step_solids = _solids(step)
    step_volume = sum(_volume(s) for s in step_solids)
    origin, pitch = np.array(node.vec("origin")), node.num("stack_pitch")
    for i, part in enumerate(boards):
        assert part.link == "neck_base"
        placed = part.shape.wrapped
        assert len(_solids(placed)) == len(step_solids) > 10   # PCB body and the component models
        assert _volume(placed) == pytest.approx(step_volume, rel=1e-7)
        shift = np.tile(origin + [0, 0, i * pitch], 2)
        assert np.allclose(_bounds(placed), _bounds(step) + shift, atol=1e-6)
    # The STEP is what mk/electronics.mk exports: a 90 x 60 mm outline centred on the origin, parts on +z.
    lo, hi = _bounds(step)[:3], _bounds(step)[3:]
    assert np.allclose([lo[0], hi[0], lo[1], hi[1]], [-45, 45, -30, 30], atol=1e-3)
    assert hi[2] > 5


# The bay's parts against each other in OpenCASCADE: well under a minute on an idle 2-core machine, past the default
# 120 s when the machine is shared (a CI run beside other builds timed out here), so these carry a longer timeout.
@pytest.mark.timeout(600)
def test_boards_sit_in_the_bay_without_interference(params, assembly):
    g = params.geometry("neck_base")
    plate_bottom = -g.node("plate").num("thickness")
    flange_top = plate_bottom - g.num("bay_height")
    base = [p for p in assembly.parts if p.link == "neck_base"]
    report = interference.check(params, Assembly(params, base), [{}])
    assert report.ok, interference.format_report(report, report.minimum)
    for part in _boards(assembly):
        bb = part.shape.BoundingBox()
        assert flange_top < bb.zmin and bb.zmax < plate_bottom, part.name


@pytest.mark.timeout(600)
def test_a_board_pushed_into_the_plate_is_caught(params, external, tmp_path):
    data = yaml.safe_load(params.path.read_text())
    # 40 mm standoffs between the boards: the top board now reaches through the base plate
    data["purchased"]["standoff-M3x40-MF"] = dict(data["purchased"]["standoff-M3x30-MF"], length=40)
    data["boards"]["standoffs"]["between"] = "standoff-M3x40-MF"
    data["boards"]["stack_pitch"] = 41.6
    path = tmp_path / "high-boards.yaml"
    path.write_text(yaml.safe_dump(data))
    moved = load(path)
    # The checker judges each pair on its two parts alone: the pair in question is all it needs to be shown.
    parts = [p for p in build_all(moved, external) if p.name in ("board_eyes-pan", "neck_base_plate")]
    assert len(parts) == 2
    report = interference.check(moved, Assembly(moved, parts), [{}])
    assert ("board_eyes-pan", "neck_base_plate") in {tuple(sorted((r.a, r.b))) for r in report.interferences}


def test_a_stack_pitch_below_the_board_height_is_named(params, external, tmp_path):
    data = yaml.safe_load(params.path.read_text())
    data["boards"]["stack_pitch"] = 10
    path = tmp_path / "tight.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ParameterError, match=r"boards\.stack_pitch: 10.0 leaves under 0.8 mm between the boards"):
        build_all(load(path), external)


def test_board_mass_is_pcb_plus_components(params, assembly, board_step, fab):
    step_solids = _solids(_read_step(board_step))
    volumes = sorted((_volume(s) for s in step_solids), reverse=True)
    materials = params.root.node("materials")
    pcb, components = volumes[0], sum(volumes[1:])   # the PCB body is by far the largest solid
    expected = (pcb * materials.num("pcb-fr4-4-layer") + components * materials.num("board-components")) * 1e-9
    board = _boards(assembly)[0]
    assert massprops.part_props(params, board).mass == pytest.approx(expected, rel=1e-6)
    assert 0.01 < expected < 0.05          # a populated 90 x 60 mm board weighs some tens of grams
    report = json.loads((fab / "reports" / "mass.json").read_text())
    assert report["boards"]["count"] == 3
    assert report["boards"]["mass_kg_each"] == pytest.approx(expected, abs=1e-5)
    base = [p for p in assembly.parts if p.link == "neck_base"]
    total = sum(massprops.part_props(params, p).mass for p in base)
    assert report["links"]["neck_base"]["mass_kg"] == pytest.approx(total, abs=1e-6)
    assert total - sum(massprops.part_props(params, p).mass for p in base if p.kind != "board") == \
        pytest.approx(3 * expected, rel=1e-6)


def test_package_records_the_board_step(fab, board_step):
    import hashlib
    manifest = json.loads((fab / "manifest.json").read_text())
    assert manifest["board_step"]["sha256"] == hashlib.sha256(board_step.read_bytes()).hexdigest(), \
        "the board STEP changed since the package was built: rebuild with make fab"
    parts = {d["design"]: d for d in json.loads((fab / "parts.json").read_text())}
    assert parts["motor_board"]["kind"] == "board" and parts["motor_board"]["quantity"] == 3
    assert parts["motor_board"]["step"] == str(board_step)


def test_the_design_hash_follows_the_step_bytes(board_step, tmp_path, params, external):
    """Same geometry, different file bytes (another export time in the header): the outputs are rebuilt."""
    text = board_step.read_text()
    changed = tmp_path / "board.step"
    changed.write_text(text.replace("FILE_NAME(", "FILE_NAME( /* re-exported */ ", 1))
    assert changed.read_bytes() != board_step.read_bytes()
    other = ext.ExternalGeometry(board_model.load(changed), external.face_plate, external.face_plate_sha256)
    first = next(p for p in build_all(params, external) if p.kind == "board")
    second = next(p for p in build_all(params, other) if p.kind == "board")
    assert first.local.Volume() == pytest.approx(second.local.Volume())
    assert design_hash(first) != design_hash(second)


def test_a_missing_board_step_stops_the_build(tmp_path):
    env = {"PYTHONPATH": f"{REPO / 'hardware' / 'head-model'}:{REPO / 'hardware' / 'mechanics'}:{REPO / 'hardware' / 'bom'}", "PATH": "/usr/bin:/bin"}
    missing = tmp_path / "no-board.step"
    result = subprocess.run([sys.executable, "-m", "robogene_head.fab", "--out", str(tmp_path / "fab"),
                             "--board-step", str(missing)], capture_output=True, text=True, env=env, timeout=300)
    assert result.returncode == 1
    assert f"fab: error: {missing}: board STEP not found" in result.stderr
    assert "Traceback" not in result.stderr


def test_an_unreadable_board_step_is_named(tmp_path):
    bad = tmp_path / "garbage.step"
    bad.write_bytes(b"\x00\x01 this is not ISO-10303-21\n")
    with pytest.raises(board_model.BoardModelError, match=rf"{bad}: not a readable STEP file"):
        board_model.load(bad)


def test_a_board_step_with_another_origin_is_named(tmp_path):
    off = tmp_path / "off-centre.step"
    cq.exporters.export(cq.Workplane().box(90, 60, 1.6, centered=False), str(off))
    with pytest.raises(board_model.BoardModelError, match=r"PCB body's centre is at \(45.000, 30.000\)"):
        board_model.load(off)
    two = tmp_path / "two-boards.step"
    cq.exporters.export(cq.Workplane().box(90, 60, 1.6).union(cq.Workplane().box(90, 60, 1.6).translate((0, 0, 5))),
                        str(two))
    with pytest.raises(board_model.BoardModelError, match=r"expected one solid spanning the board outline"):
        board_model.load(two)
