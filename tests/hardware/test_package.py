# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The fabrication package is complete, its manifest checksums hold, its files open in real tools, and a
second build rebuilds nothing."""
import hashlib
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from conftest import FAB, REPO


def test_manifest_checksums_match(fab):
    manifest = json.loads((fab / "manifest.json").read_text())
    listed = {f["path"] for f in manifest["files"]}
    from robogene_head.fab import PACKAGE_ENTRIES
    on_disk = {str(p.relative_to(fab)) for p in fab.rglob("*") if p.is_file() and p.relative_to(fab).parts[0] in PACKAGE_ENTRIES}
    assert listed == on_disk
    for f in manifest["files"]:
        assert hashlib.sha256((fab / f["path"]).read_bytes()).hexdigest() == f["sha256"], f["path"]
    params_sha = hashlib.sha256((REPO / "hardware" / "head-parameters.yaml").read_bytes()).hexdigest()
    assert manifest["parameters_sha256"] == params_sha, "package is stale: rebuild with make fab"


def test_every_part_has_its_files(fab, assembly):
    designs = {p.design: p for p in assembly.parts}
    for design, part in designs.items():
        if part.kind == "board":   # the board's STEP is the electronics package's (test_boards.py)
            assert not (fab / "step" / f"{design}.step").exists()
            continue
        assert (fab / "step" / f"{design}.step").stat().st_size > 1000, design
        if part.kind == "printed":
            assert (fab / "stl" / f"{design}.stl").exists(), design
        if part.kind == "machined":
            assert (fab / "drawings" / f"{design}.svg").exists(), design
            assert (fab / "drawings" / f"{design}.pdf").exists(), design
    for printable in ("camera_spacer", "cable_clip", "face_plate"):
        assert (fab / "stl" / f"{printable}.stl").exists()
    assert (fab / "assembly" / "robogene_head.step").exists()


# glTF is y-up: its (x, y, z) is the head's (x, z, -y)
GLTF_TO_HEAD = np.array([[1, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1]], dtype=float)


def test_glb_holds_every_part_where_the_assembly_puts_it(fab, assembly):
    """One node per part instance (so every design is there), each with meshes that fill the part's bounding box
    at the zero pose."""
    import trimesh
    scene = trimesh.load(str(fab / "assembly" / "robogene_head.glb"))
    graph = scene.graph
    children = {}
    for parent, child, _ in graph.to_edgelist():
        children.setdefault(parent, []).append(child)
    assert set(children["robogene_head"]) == {p.name for p in assembly.parts}
    assert {p.design for p in assembly.parts} == {p.design for p in assembly.parts if p.name in children["robogene_head"]}
    for placed in assembly.pose({}):
        stack, meshes = [placed.part.name], []
        while stack:
            node = stack.pop()
            stack += children.get(node, [])
            transform, geometry = graph[node]
            if geometry is not None:
                meshes.append(scene.geometry[geometry].copy().apply_transform(GLTF_TO_HEAD @ transform))
        assert meshes, placed.part.name
        lo = np.min([m.bounds[0] for m in meshes], axis=0)
        hi = np.max([m.bounds[1] for m in meshes], axis=0)
        bb = placed.shape.BoundingBox()
        # meshes lie on the surfaces: their box is inside the exact one, short of it by the chordal deviation
        assert np.allclose(lo, [bb.xmin, bb.ymin, bb.zmin], atol=0.5), placed.part.name
        assert np.allclose(hi, [bb.xmax, bb.ymax, bb.zmax], atol=0.5), placed.part.name


def test_freecad_reopened_every_step(fab, assembly):
    report = json.loads((fab / "reports" / "freecad-step-check.json").read_text())
    files = {r["file"]: r for r in report["files"]}
    assert set(files) == {f"{d}.step" for d in {p.design for p in assembly.parts if p.kind != "board"}} | \
        {"robogene_head.step"}
    assert all(r["ok"] for r in files.values()), [r for r in files.values() if not r["ok"]]
    # one solid per part, and the board's PCB body and component models three times over
    boards = [p for p in assembly.parts if p.kind == "board"]
    assert len(boards) == 3 and all(p.expected_solids > 10 for p in boards)
    assert files["robogene_head.step"]["solids"] == len(assembly.parts) - 3 + sum(p.expected_solids for p in boards)


def test_freecad_check_catches_a_wrong_step(fab, tmp_path):
    """The independent check is real: a STEP whose volume differs from what CadQuery reported fails."""
    from robogene_head import freecad
    step = fab / "step" / "neck_upright_drive.step"
    report = freecad.check_steps([step], {"neck_upright_drive": 1000.0}, tmp_path / "check.json")
    (entry,) = report["files"]
    assert not entry["ok"] and "volume" in entry["problem"]
    broken = tmp_path / "step" / "broken.step"
    broken.parent.mkdir(parents=True, exist_ok=True)
    broken.write_text(step.read_text()[:2000])
    report = freecad.check_steps([broken], {"broken": 1.0}, tmp_path / "check.json")
    assert not report["files"][0]["ok"]


def test_drawings_are_svg_that_rasterise(fab, tmp_path):
    svgs = sorted((fab / "drawings").glob("*.svg"))
    assert svgs
    for svg in svgs:
        png = tmp_path / (svg.stem + ".png")
        subprocess.run(["rsvg-convert", "-d", "40", "-p", "40", "-o", str(png), str(svg)], check=True,
                       capture_output=True, timeout=60)
        assert png.stat().st_size > 2000, svg.name


def test_renders_show_something(fab):
    import vtk
    pngs = sorted((fab / "renders").glob("*.png"))
    assert len(pngs) >= 4
    for png in pngs:
        reader = vtk.vtkPNGReader()
        reader.SetFileName(str(png))
        reader.Update()
        image = reader.GetOutput()
        w, h, _ = image.GetDimensions()
        from vtk.util.numpy_support import vtk_to_numpy
        pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[..., :3].astype(int)
        # not a blank frame: the head covers a good part of the picture and has many colours
        background = pixels[0, 0]
        covered = np.mean(np.abs(pixels - background).sum(axis=2) > 60)
        assert 0.08 < covered < 0.9, (png.name, covered)
        assert len(np.unique(pixels.reshape(-1, 3), axis=0)) > 500, png.name


# A no-op rebuild still builds all 154 parts to hash them: past the default 120 s on a 2-core machine since the
# assembly grew (harness, stops, circlips), so it carries a longer timeout.
@pytest.mark.timeout(600)
def test_second_build_rebuilds_nothing(fab, tmp_path):
    # The second build runs on a copy (its files' times kept): even a build that rebuilds nothing rewrites the reports
    # and the manifest, which the tests running beside this one (pytest -n) read from the package.
    original, fab = fab, tmp_path / "fab"
    shutil.copytree(original, fab, symlinks=True)
    stamp = {p: p.stat().st_mtime_ns for p in fab.rglob("*") if p.is_file() and
             p.suffix in (".step", ".stl", ".svg", ".pdf", ".png", ".glb")}
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(REPO / "hardware" / "head-model"), str(REPO / "hardware" / "mechanics"),
                                                   str(REPO / "hardware" / "bom")]))
    # Same inputs as the build that made the package (make passes the board BOMs and the board STEP).
    sources = json.loads((fab / "bom" / "sources.json").read_text())
    boards = [arg for b in sources["board_boms"] for arg in ("--board-bom", f"{b['path']}:{b['copies']}")]
    boards += ["--board-step", json.loads((fab / "manifest.json").read_text())["board_step"]["path"]]
    before = (fab / "bom" / "robogene-head-bom.csv").read_bytes()
    result = subprocess.run([sys.executable, "-m", "robogene_head.fab", "--out", str(fab), "--batch", str(sources["batch"]),
                             *boards], capture_output=True, text=True, env=env, timeout=900)
    assert result.returncode == 0, result.stderr[-3000:]
    assert "export" not in result.stderr.replace("exports", "")
    after = {p: p.stat().st_mtime_ns for p in stamp}
    assert after == stamp
    assert (fab / "bom" / "robogene-head-bom.csv").read_bytes() == before


def _make_fab_commands(*variables: str) -> str:
    """The commands `make fab` would run, without running them (-n), for the given make variables."""
    result = subprocess.run(["make", "-n", "-C", str(REPO), "fab", *variables], capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr[-2000:]
    return result.stdout


def test_make_batch_prices_the_bom_for_that_many_heads():
    assert "--batch 12" in _make_fab_commands("BATCH=12")
    default = _make_fab_commands("BATCH=")
    assert "robogene_head.fab" in default and "--batch" not in default


@pytest.mark.parametrize("value, message", [("0", "BATCH must be at least 1 head, got 0"),
                                            ("two", "BATCH must be a whole number of heads, got 'two'")])
def test_a_bad_batch_is_named(value, message, capsys):
    from robogene_head import fab as fab_cli
    with pytest.raises(SystemExit) as exit_:
        fab_cli.main(["--batch", value])
    assert exit_.value.code == 2 and message in capsys.readouterr().err
