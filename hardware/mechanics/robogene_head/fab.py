# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Build the head's fabrication package into build/fab/ (python -m robogene_head.fab --out build/fab).

Each output is keyed by a content hash of what it is made from (the part's exact B-rep, the placements,
the parameter file...), so a second run only rebuilds what changed. Any failed check stops the build
with a message naming the part and the defect."""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import subprocess
import sys
import time
from contextlib import contextmanager
from pathlib import Path

import numpy as np

from robogene_head_model import joint_config
from robogene_head_model.params import ParameterError, load

from . import external as external_mod
from . import (bearing_arrangement, bearing_loads, drive_sizing, eye_accuracy, fits, freecad, kinematics,
               massprops, openscad, render, render_steps, sequence, threads, torque_path, unpowered, urdf)
from .assembly import Assembly
from .board_model import BoardModelError
from .cache import Cache, code_digest, digest
from .checks import assembly_sequence, board_bay, interference, joint_encoders, mesh, validity
from .export import link_solid, shape_hash, write_step, write_stl
from .harness import build as harness_build
from .harness.pinout import PinoutError
from .mesh_solid import MeshSolidError
from .parts import board_plugs
from .progress import Progress

MECHANICS = Path(__file__).resolve().parents[1]
REPO = MECHANICS.parents[1]
DEFAULT_BOARD_STEP = REPO / "build" / "fab" / "electronics" / "board.step"   # mk/electronics.mk


class BuildError(RuntimeError):
    pass


@contextmanager
def _fails_build(*errors: type[Exception]):
    """One of errors, raised by a check's enforce or a step, stops the build with the error's own message."""
    try:
        yield
    except errors as exc:
        raise BuildError(str(exc)) from None


def _write_report(out: Path, name: str, table: str, data: str) -> None:
    """reports/<name>.txt (the table a reader reads) and reports/<name>.json (the same for tools), written before
    the check's verdict so that the package holds them whether or not it passes."""
    _write(out / "reports" / f"{name}.txt", table + "\n")
    _write(out / "reports" / f"{name}.json", data)


def _placement_key(part) -> list:
    m = part.placement.wrapped.Transformation()
    return [round(m.Value(i, j), 9) for i in (1, 2, 3) for j in (1, 2, 3, 4)]


def design_hash(part) -> str:
    """What a design's outputs are made from: its exact B-rep, kind and materials, and the bytes of the file it
    was read from (the board STEP, the face plate STL), so a changed source file rebuilds everything made from it."""
    return shape_hash(part.local, part.kind, part.material, part.source_sha256, *part.solid_materials)


def designs_of(parts):
    out = {}
    for part in parts:
        entry = out.setdefault(part.design, {"part": part, "instances": []})
        entry["instances"].append(part.name)
    return out


def build(out: Path, params_path: Path | None, board_boms: list[Path], batch: int | None, progress: Progress,
          board_step: Path = DEFAULT_BOARD_STEP) -> dict:
    out = out.resolve()   # FreeCAD runs in a scratch directory: every path it gets must be absolute
    out.mkdir(parents=True, exist_ok=True)
    cache = Cache(out / ".cache" / "state.json")
    params = load(params_path)
    params_text = params.path.read_bytes()

    # 0. OpenSCAD printables first: the face plate joins the assembly from its STL.
    scad_defines = openscad.defines(params)
    scads = openscad.sources()
    for i, scad in enumerate(scads):
        values = scad_defines.get(scad.stem, {})
        target = out / "stl" / f"{scad.stem}.stl"
        key = digest(scad.read_bytes(), values)
        fresh = cache.fresh(f"scad:{scad.stem}", key, [target])
        progress.step("openscad", i, len(scads), scad.stem, "unchanged" if fresh else "render")
        if not fresh:
            openscad.render_stl(scad, values, target)
            cache.record(f"scad:{scad.stem}", key)
    with _fails_build(BoardModelError, MeshSolidError):
        external = external_mod.load(Path(board_step).resolve(), out / "stl" / f"{external_mod.FACE_PLATE}.stl")
    assembly = Assembly(params, external=external)
    parts = assembly.parts
    progress.note(f"{len(parts)} parts from {params.path} and {external.board.path}")

    # 1. Every part is one valid solid.
    bad = [c for c in validity.check_all(parts) if not c.ok]
    if bad:
        raise BuildError("invalid solids: " + "; ".join(
            f"{c.name} (valid={c.valid}, solids={c.solids}, closed={c.closed}, volume={c.volume:.3f})" for c in bad))

    # 1b. Each joint encoder's board at the AS5048A's air gap over its magnet, its IC on the magnet's axis, over the
    # joint's range (checks/joint_encoders.py): the table goes into the package whether or not it passes.
    encoders = joint_encoders.check(params, parts)
    _write_report(out, "joint-encoders", joint_encoders.format_report(encoders),
                  json.dumps(joint_encoders.report_json(encoders), indent=1))
    if not encoders.ok:
        raise BuildError("joint-encoder check failed: " + "; ".join(encoders.failures) + ", see "
                         + str(out / "reports" / "joint-encoders.txt"))

    # 2. STEP per designed/purchased part, STL per printed part. The board's STEP is the electronics package's
    # own; the OpenSCAD printables' STLs are OpenSCAD's.
    designs = designs_of(parts)
    hashes = {}
    summary = []
    for i, (design, entry) in enumerate(sorted(designs.items())):
        part = entry["part"]
        h = design_hash(part)
        hashes[design] = h
        row = {"design": design, "kind": part.kind, "material": part.material, "quantity": len(entry["instances"]),
               "instances": entry["instances"], "volume_mm3": round(part.local.Volume(), 3), "hash": h}
        if part.kind == "board":
            summary.append(dict(row, step=str(external.board.path), solids=part.expected_solids))
            continue
        outputs = [out / "step" / f"{design}.step"]
        own_stl = part.kind == "printed" and not part.source_sha256
        if own_stl:
            outputs.append(out / "stl" / f"{design}.stl")
        fresh = cache.fresh(f"design:{design}", h, outputs)
        progress.step("parts", i, len(designs), design, "unchanged" if fresh else "export")
        if not fresh:
            write_step(part.local, outputs[0], design)
            if own_stl:
                write_stl(part.local, outputs[1])
            cache.record(f"design:{design}", h)
        summary.append(row)
    _remove_stale(out / "step", {f"{d}.step" for d, e in designs.items() if e["part"].kind != "board"}, progress)
    _remove_stale(out / "stl", {f"{d}.stl" for d, e in designs.items() if e["part"].kind == "printed"} |
                  {f"{s.stem}.stl" for s in openscad.sources()}, progress)
    machined_designs = {d for d, e in designs.items() if e["part"].kind == "machined"}
    _remove_stale(out / "drawings", {f"{d}.{ext}" for d in machined_designs for ext in ("pdf", "svg")}, progress)
    # 2b. The wiring harness: cable routes checked over the joints' ranges, drawn with WireViz; its parts go to the BOM.
    sys.path.insert(0, str(REPO / "hardware" / "bom"))
    from robogene_bom import catalog as catalog_mod
    from robogene_bom.catalog import CatalogError
    geometry_key = digest([(p.name, hashes[p.design], p.link, _placement_key(p)) for p in parts],
                          [(j.name, j.parent, j.child, j.origin, j.axis, j.lower, j.upper) for j in params.joints.values()])
    with _fails_build(harness_build.HarnessError, PinoutError, CatalogError, RuntimeError):
        harness_lines = harness_build.build(params, parts, out, cache, catalog_mod.load(), progress, geometry_key)

    # 3. Link meshes for the URDF, mass properties, URDF. The meshes leave out the boards (inside the skirt;
    # KiCad's component models are not watertight meshes); their mass is in the inertias.
    links = kinematics.links(params)
    for i, link in enumerate(links):
        link_parts = [p for p in parts if p.link == link and p.kind != "board"]
        key = digest([(p.name, hashes[p.design], _placement_key(p)) for p in link_parts])
        target = out / "urdf" / "meshes" / f"{link}.stl"
        fresh = cache.fresh(f"link:{link}", key, [target])
        progress.step("meshes", i, len(links), link, "unchanged" if fresh else "fuse+mesh")
        if not fresh:
            write_stl(link_solid(link_parts), target)
            cache.record(f"link:{link}", key)
    props = massprops.link_props(params, parts)
    (out / "urdf").mkdir(parents=True, exist_ok=True)
    (out / "urdf" / "robogene_head.urdf").write_text(urdf.generate(params, props))
    _write(out / "config" / "head-joints.json", json.dumps(joint_config.config(params), indent=1))
    mass_report = mass_summary(params, props, [p for p in parts if p.kind == "board"])
    _write(out / "reports" / "mass.json", json.dumps(mass_report, indent=1))

    # 3b. Drives sized by a check (drive_sizing): the table goes into the package whether or not it passes.
    progress.note("drive sizing: worst case over the whole range")
    sizing = drive_sizing.size(params, props)
    _write_report(out, "drive-sizing", drive_sizing.format_table(sizing), drive_sizing.dumps(sizing))
    with _fails_build(drive_sizing.SizingError):
        drive_sizing.enforce(sizing)
    progress.note("drive sizing: every drive within its continuous ratings, smallest margin "
                  f"{min(j.margin for j in sizing.joints):.2f} ({drive_sizing.required_margin(params):g} required)")
    # Each joint's torque path against its drive's peak torque: the table goes into the package whether or not it
    # passes, and the build fails on an element that would slip or break before the drive stalls (before the
    # bearing loads, which the same peak sets).
    torque = torque_path.analyse(params)
    _write_report(out, "torque-path", torque_path.format_table(torque), torque_path.dumps(torque))
    with _fails_build(torque_path.TorquePathError):
        torque_path.enforce(torque)
    # What each joint does when the power goes, against its holding element: the table goes into the package whether
    # or not it passes, and the build fails where the head would fall (unpowered.enforce).
    released = unpowered.analyse(params, props, {j.joint: j.gravity_Nm for j in sizing.joints})
    _write_report(out, "unpowered", unpowered.format_table(released), unpowered.dumps(released))
    with _fails_build(unpowered.UnpoweredError):
        unpowered.enforce(released)
    # The bearings against their static load rating: the table goes into the package whether or not it passes.
    loads = bearing_loads.analyse(params, parts, props)
    _write_report(out, "bearing-loads", bearing_loads.format_table(loads), bearing_loads.dumps(loads))
    with _fails_build(bearing_loads.BearingLoadError):
        bearing_loads.enforce(loads)
    # One fixed and one floating bearing per shaft, measured in the CAD: the report goes into the package whether or
    # not it passes.
    arrangement = bearing_arrangement.analyse(params, parts)
    _write_report(out, "bearing-arrangement", bearing_arrangement.format_report(arrangement),
                  bearing_arrangement.dumps(arrangement))
    with _fails_build(bearing_arrangement.BearingArrangementError):
        bearing_arrangement.enforce(arrangement)
    # The eyes' error against the stereo budget, term by term: reported, so that docs/fabricate.md states it from the
    # package. It does not fail the build yet: the eye pans' 16/7 spur gearheads miss the budget (eye_accuracy.enforce
    # is the check, for when a drive meets it; see docs/fabricate.md, "Eyes for stereo").
    eyes = eye_accuracy.budget(params, {j.joint: j.load_Nm for j in sizing.joints})
    _write_report(out, "eye-accuracy", eye_accuracy.format_report(eyes), eye_accuracy.dumps(eyes))
    progress.note("eye accuracy: the pan drives " + ("meet" if eyes.ok else "do NOT meet") + " the stereo budget, "
                  "see " + str(out / "reports" / "eye-accuracy.txt"))

    # 4. Assembly STEP and GLB at the zero pose.
    asm_out = [out / "assembly" / "robogene_head.step", out / "assembly" / "robogene_head.glb"]
    if not cache.fresh("assembly", geometry_key, asm_out):
        progress.note("assembly STEP + GLB")
        asm_out[0].parent.mkdir(parents=True, exist_ok=True)
        cq_assy = assembly.to_cq()
        cq_assy.export(str(asm_out[0]), "STEP")
        cq_assy.export(str(asm_out[1]), "GLTF")
        cache.record("assembly", geometry_key)

    # 6. Every mesh watertight and manifold.
    stls = sorted((out / "stl").glob("*.stl")) + sorted((out / "urdf" / "meshes").glob("*.stl"))
    mesh_results = []
    for i, path in enumerate(stls):
        progress.step("mesh-check", i, len(stls), path.name)
        mesh_results.append(mesh.check_stl(path))
    _write(out / "reports" / "meshes.json", json.dumps([dict(vars(m), ok=m.ok, defects=m.defects) for m in mesh_results], indent=1))
    bad_meshes = [m for m in mesh_results if not m.ok]
    if bad_meshes:
        raise BuildError("mesh defects: " + "; ".join(
            f"{Path(m.path).name}: {m.boundary_edges} open, {m.nonmanifold_edges} non-manifold, "
            f"{m.misoriented_edges} misoriented edges, {m.degenerate_faces} degenerate faces, volume {m.volume:.1f}"
            for m in bad_meshes))

    # 6b. The board bay with the harness plugged in: every mated plug and its wires clear of the boards above, the
    # standoffs and the plate (checks/board_bay.py). The plugs join the interference sweep below; they are the
    # harness's parts, counted in the BOM with it, not parts of the assembly.
    with _fails_build(PinoutError):
        plugs = board_plugs.build(params, external.board)
    bay = board_bay.check(params, parts, plugs)
    _write(out / "reports" / "board-bay.txt", board_bay.format_report(bay) + "\n")
    if not bay.ok:
        raise BuildError("board-bay check failed (a mated plug without room), see " + str(out / "reports" / "board-bay.txt"))
    progress.note(f"board bay: {len(plugs)} mated plugs, each at least {bay.minimum:g} mm from the other parts")

    # 7. Interference and clearance over the joint sweep (the slow step: cached on the geometry).
    inter_out = [out / "reports" / "interference.txt", out / "reports" / "interference.json"]
    # A change to the checker itself (or to how it meshes the parts) must re-run it, as a change to the geometry does.
    inter_key = digest(geometry_key, code_digest(interference),
                       [(q.part.name, shape_hash(q.part.local), _placement_key(q.part)) for q in plugs])
    if not cache.fresh("interference", inter_key, inter_out):
        poses = interference.sweep_poses(params)
        # the plugs against the neck base's own parts are the board-bay check's (above): here only against what moves
        report = interference.check(params, Assembly(params, parts + [q.part for q in plugs]), poses,
                                    progress=lambda i, n: progress.step("sweep", i, n, f"pose {i + 1}"),
                                    static_checked_elsewhere=frozenset(q.part.name for q in plugs))
        minimum = params.geometry("clearances").num("minimum")
        _write(inter_out[0], interference.format_report(report, minimum) + "\n")
        _write(inter_out[1], json.dumps(interference.report_json(report, minimum), indent=1))
        if not report.ok:
            raise BuildError("interference check failed, see " + str(inter_out[0]))
        cache.record("interference", inter_key)

    # 7b. The assembly sequence: every step possible from outside (swept insertion, presses, every screw's driver),
    # then a picture per step and the instructions page. Cached on the geometry, the sequence and the checker.
    _assembly_sequence(out, cache, progress, params, assembly, geometry_key)

    # 8. FreeCAD re-opens every STEP (independent kernel check) and draws the machined parts.
    step_files = [out / "step" / f"{d['design']}.step" for d in summary if d["kind"] != "board"] + [asm_out[0]]
    expected = {d["design"]: d["volume_mm3"] for d in summary if d["kind"] != "board"}
    expected["robogene_head"] = round(sum(p.local.Volume() for p in parts), 3)
    solids = {"robogene_head": sum(p.expected_solids for p in parts)}
    check_report = out / "reports" / "freecad-step-check.json"
    check_key = digest(geometry_key, sorted(expected.items()), sorted(solids.items()), freecad.check_digest())
    if not cache.fresh("freecad-check", check_key, [check_report]):
        progress.note(f"FreeCAD: re-open {len(step_files)} STEP files")
        with _fails_build(RuntimeError, OSError, subprocess.TimeoutExpired):
            freecad.check_steps(step_files, expected, check_report, solids)
        cache.record("freecad-check", check_key)
    fc_report = json.loads(check_report.read_text())
    bad_steps = [r for r in fc_report["files"] if not r["ok"]]
    if bad_steps:
        raise BuildError("FreeCAD rejected: " + "; ".join(f"{r['file']}: {r['problem']}" for r in bad_steps))
    densities = params.root.node("materials")
    machined = [d for d in summary if d["kind"] == "machined"]
    tapped = threads.tapped_holes(params, parts)
    fitted = fits.find(params, parts)
    _write(out / "reports" / "fits.json", json.dumps(
        {design: [dict(vars(f), text=f.text()) for f in found] for design, found in sorted(fitted.items())}, indent=1))
    _draw_machined(out, cache, progress, [freecad.DrawingJob(
        d["design"], out / "step" / f"{d['design']}.step", d["material"], densities.num(d["material"]),
        " ".join(n for n in (designs[d["design"]]["part"].note,
                             fits.note(fitted[d["design"]]) if d["design"] in fitted else "") if n),
        d["hash"][:8], f"step/{d['design']}.step",
        [h.as_dict() for h in tapped.get(d["design"], [])]) for d in machined])

    # 9. Renders at a few joint poses.
    render_out = [out / "renders" / f"{view.name}.png" for view in render.VIEWS]
    render_key = digest(geometry_key, [vars(v) for v in render.VIEWS], code_digest(render))
    if not cache.fresh("renders", render_key, render_out):
        for i, view in enumerate(render.VIEWS):
            progress.step("render", i, len(render.VIEWS), view.name)
            render.render(assembly, view, render_out[i])
        cache.record("renders", render_key)
    _remove_stale(out / "renders", {p.name for p in render_out}, progress)

    # 10. Bill of materials.
    from robogene_bom import build as bom_build
    from robogene_bom.board import BoardBomError
    progress.note("BOM")
    with _fails_build(CatalogError, BoardBomError):
        bom_build.write_package(params, parts, board_boms, out / "bom", batch=batch, extras=harness_lines)

    # 11. Summary and manifest with checksums.
    _write(out / "parts.json", json.dumps(summary, indent=1))
    manifest = write_manifest(out, params_text, external.board)
    progress.note(f"done: {len(manifest['files'])} files in {out}")
    return manifest


def _assembly_sequence(out: Path, cache: Cache, progress: Progress, params, assembly, geometry_key: str,
                       sequence_path: Path | None = None) -> None:
    """Check the assembly sequence (BuildError naming the step and the parts on failure), then draw its steps."""
    with _fails_build(sequence.SequenceError):
        seq = sequence.load([p.name for p in assembly.parts], sequence_path)
    reports = [out / "reports" / "assembly.txt", out / "reports" / "assembly.json"]
    key = digest(geometry_key, seq.path.read_bytes(), code_digest(assembly_sequence), params.path.read_bytes())
    if not cache.fresh("assembly-sequence", key, reports):
        report = assembly_sequence.check(params, assembly, seq,
                                         progress=lambda i, n, label: progress.step("assembly", i, n, label))
        _write(reports[0], assembly_sequence.format_report(report) + "\n")
        _write(reports[1], json.dumps(assembly_sequence.report_json(report), indent=1))
        progress.note(f"assembly sequence checked in {report.seconds:.0f} s ({report.cpu_seconds:.0f} s of CPU)")
        if not report.ok:
            raise BuildError("assembly sequence check failed (" + str(seq.path.name) + "):\n  "
                             + "\n  ".join(str(p) for p in report.problems) + f"\nsee {reports[0]}")
        cache.record("assembly-sequence", key)
    folder = out / "assembly" / "steps"
    steps = seq.steps()
    pictures = [folder / s.picture(i + 1) for i, s in enumerate(steps)]
    page = folder / "README.md"
    picture_key = digest(key, code_digest(render_steps))
    if not cache.fresh("assembly-steps", picture_key, pictures + [page]):
        render_steps.render_all(assembly, seq, folder,
                                progress=lambda i, n, label: progress.step("steps", i, n, label))
        _write(page, render_steps.instructions(seq, json.loads(reports[1].read_text())))
        cache.record("assembly-steps", picture_key)
    _remove_stale(folder, {p.name for p in pictures} | {page.name}, progress)


def _draw_machined(out: Path, cache: Cache, progress: Progress, jobs: list) -> None:
    """TechDraw drawings (PDF + SVG) of the machined parts; only parts whose geometry, material, note, tapped
    holes or drawing code changed are redrawn, all of them in one FreeCAD session. reports/drawings.json lists every
    drawing's sheet, scale and dimensions."""
    report_path = out / "reports" / "drawings.json"
    try:
        report = {d["name"]: d for d in json.loads(report_path.read_text())["drawings"]}
    except (OSError, ValueError, KeyError):
        report = {}
    code = freecad.drawing_digest()
    keys = {j.name: digest(j.name, j.material, j.density, j.note, j.revision, j.source, j.threads, code) for j in jobs}
    outputs = {j.name: [out / "drawings" / f"{j.name}.pdf", out / "drawings" / f"{j.name}.svg"] for j in jobs}
    stale = [j for j in jobs if not (cache.fresh(f"drawing:{j.name}", keys[j.name], outputs[j.name]) and j.name in report)]
    for i, j in enumerate(j for j in jobs if j not in stale):
        progress.step("drawings", i, len(jobs), j.name, "unchanged")
    done = len(jobs) - len(stale)
    if stale:
        progress.note(f"FreeCAD TechDraw: drawing {len(stale)} machined parts in one session")
        with _fails_build(RuntimeError, OSError):
            data = freecad.draw(stale, out / "drawings",
                                on_progress=lambda i, n, line: progress.step("drawings", done + i, len(jobs), line))
        for d in data["drawings"]:
            report[d["name"]] = d
            cache.record(f"drawing:{d['name']}", keys[d["name"]])
    names = {j.name for j in jobs}
    _write(report_path, json.dumps({"drawings": [report[n] for n in sorted(report) if n in names]}, indent=1))


def _remove_stale(folder: Path, keep: set[str], progress: Progress) -> None:
    """Outputs of designs that no longer exist must not linger in the package."""
    if not folder.is_dir():
        return
    for path in sorted(folder.iterdir()):
        if path.is_file() and path.name not in keep:
            progress.note(f"removing stale {path.relative_to(folder.parent)}")
            path.unlink()


def mass_summary(params, props, boards) -> dict:
    head_links = ["head_frame", "eyes_tilt_link", "left_eye", "right_eye"]
    poses = kinematics.link_poses(params, {})
    head_frame = poses["head_frame"]
    # The moving head (everything above the yaw joint) in the head frame, at the zero pose.
    moved = [props[l].moved(np.linalg.inv(head_frame) @ poses[l]) for l in head_links if l in props]
    head = massprops.combine(moved)
    ref = params.root.node("reference")
    ref_i = ref.node("head_inertia_kgmm2")
    out = {"links": {}, "head_above_yaw": {}, "reference": {}, "boards": {}}
    for link, mp in props.items():
        out["links"][link] = {"mass_kg": round(mp.mass, 7), "com_mm": [round(v, 3) for v in mp.com],
                              "inertia_kgmm2": [[round(v, 3) for v in row] for row in mp.inertia]}
    out["head_above_yaw"] = {"mass_kg": round(head.mass, 5), "com_mm": [round(v, 3) for v in head.com],
                             "inertia_kgmm2": [[round(v, 3) for v in row] for row in head.inertia]}
    if boards:
        each = massprops.part_props(params, boards[0])
        out["boards"] = {"count": len(boards), "link": boards[0].link, "mass_kg_each": round(each.mass, 5),
                         "materials": {m: params.root.node("materials").num(m) for m in sorted(set(boards[0].solid_materials))},
                         "note": "PCB body and KiCad component models at the densities of materials; parts without a "
                                 "3-D model in the board STEP are not counted"}
    out["reference"] = {"source": "iCub 2.7 standard head, public CAD export (see docs/fabricate.md)",
                        "mass_kg": ref.num("head_mass"),
                        "inertia_kgmm2_diag": [ref_i.num("xx"), ref_i.num("yy"), ref_i.num("zz")],
                        "mass_ratio": round(head.mass / ref.num("head_mass"), 4),
                        "inertia_ratio_diag": [round(head.inertia[k, k] / ref_i.num(a), 4)
                                               for k, a in enumerate(("xx", "yy", "zz"))]}
    return out


def _write(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)


# The package's own top-level entries; other areas (build/fab/electronics) keep their own manifests.
PACKAGE_ENTRIES = ("assembly", "bom", "config", "drawings", "harness", "renders", "reports", "step", "stl", "urdf",
                   "parts.json")


def write_manifest(out: Path, params_text: bytes, board) -> dict:
    files = []
    for path in sorted(out.rglob("*")):
        rel = path.relative_to(out)
        if path.is_dir() or rel.parts[0] not in PACKAGE_ENTRIES:
            continue
        files.append({"path": str(rel), "bytes": path.stat().st_size,
                      "sha256": hashlib.sha256(path.read_bytes()).hexdigest()})
    manifest = {"package": "robogene-head fabrication package",
                "parameters_sha256": hashlib.sha256(params_text).hexdigest(),
                "board_step": {"path": str(board.path), "sha256": board.sha256}, "files": files}
    _write(out / "manifest.json", json.dumps(manifest, indent=1))
    _write(out / "SHA256SUMS", "".join(f"{f['sha256']}  {f['path']}\n" for f in files))
    return manifest


def _heads(text: str) -> int:
    """A batch size from the command line (make's BATCH=): a whole number of heads, at least one."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"BATCH must be a whole number of heads, got {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"BATCH must be at least 1 head, got {value}")
    return value


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=REPO / "build" / "fab")
    ap.add_argument("--params", type=Path, default=None)
    ap.add_argument("--board-bom", action="append", default=[],
                    help="CSV BOM of a KiCad board (Reference, Value, Footprint, MPN, Qty), merged boards.count times "
                         "per head, or PATH:N for N copies; repeatable")
    ap.add_argument("--batch", type=_heads, default=None, help="number of heads for the batch cost (default: parameter file)")
    ap.add_argument("--board-step", type=Path, default=DEFAULT_BOARD_STEP,
                    help="the motor-control board's STEP from KiCad, placed boards.count times (default: %(default)s)")
    args = ap.parse_args(argv)
    progress = Progress()
    started = time.monotonic()
    try:
        build(args.out, args.params, args.board_bom, args.batch, progress, args.board_step)
    except (ParameterError, BuildError) as exc:
        print(f"fab: error: {exc}", file=sys.stderr)
        return 1
    progress.note(f"fabrication package built in {time.monotonic() - started:.0f} s")
    return 0


if __name__ == "__main__":
    os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    sys.exit(main())
