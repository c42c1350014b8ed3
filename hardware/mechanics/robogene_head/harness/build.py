# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The harness step of the fabrication build: plan the harness from the parameters and the assembly, write its
report, stop the build when a cable is over its bend radius or twist limit, passes through a part or hangs from a
clamp nothing holds (clearance.py; but for the spans harness.unresolved names) or runs into another span's cables
(crossing.py), draw it with WireViz and picture
its routes among the parts (picture.py) into build/fab/harness/, and hand its BOM lines to the BOM. Cached on
everything it is made from, in two stages: a changed catalog only redraws the WireViz drawings (they name the
mating parts by MPN), without sweeping the spans again."""
from __future__ import annotations

import hashlib
import json
import sys
from pathlib import Path

from robogene_head_model.params import HeadParameters

from ..cache import Cache, code_digest, digest
from . import clearance, crossing, drawing, picture, pinout, plan, report, spec


class HarnessError(RuntimeError):
    """A harness check failed; the message lists every violation and names the report."""


def _checks_key(params: HeadParameters, parts, geometry: str) -> str:
    """Everything the plan and its checks are made from: parameters, its code, the board's pinout sources, and every
    part's geometry, link and placement (`geometry`, the caller's digest of them: the cables' far ends are parts'
    centres, and the spans' clearance depends on all parts)."""
    # its own code and all it uses (the part meshing of clearance.py, the picture's stage in render.py)
    code = code_digest(sys.modules[__name__])
    board = [hashlib.sha256(p.read_bytes()).hexdigest() for p in (pinout.PCB, pinout.GENERATOR / "design.py")]
    return digest(params.path.read_bytes(), code, board, [p.name for p in parts], geometry)


def _drawings_key(checks: str, catalog) -> str:
    """And the catalog: the drawings name the mating parts by MPN."""
    return digest(checks, hashlib.sha256(Path(catalog.path).read_bytes()).hexdigest())


def build(params: HeadParameters, parts, out: Path, cache: Cache, catalog, progress,
          geometry: str) -> list[tuple[str, float, str]]:
    """Returns the harness's BOM lines (catalog key, quantity per head, what for). geometry: a digest of every part's
    shape and placement."""
    folder, reports = out / "harness", out / "reports"
    data, text = folder / "harness.json", reports / "harness.txt"
    pictures = [folder / f"{pic.name}.png" for pic in picture.PICTURES]
    checks_key = _checks_key(params, parts, geometry)
    drawings_key = _drawings_key(checks_key, catalog)
    if cache.fresh("harness", drawings_key, [data, text]):
        progress.note("harness: unchanged")
        return _bom(json.loads(data.read_text()))
    if cache.fresh("harness-checks", checks_key, [data, text] + pictures):
        # only the catalog changed: the plan (a second) for the drawings, the checks' results as they were
        progress.note("harness: checks unchanged; WireViz drawings for the changed catalog")
        h = plan.plan(params, spec.load(params), parts)
        _keep_only(folder, drawing.write(h, catalog, folder) + pictures + [data])
        cache.record("harness", drawings_key)
        return _bom(json.loads(data.read_text()))
    progress.note("harness: sweeping the free spans over their joints' ranges")
    h = plan.plan(params, spec.load(params), parts)
    progress.note("harness: the spans' clearance of the parts")
    spans_clear = clearance.check(params, h, parts, clearance.unresolved(params, h))
    progress.note("harness: the spans' cables against each other")
    spans_clear.crossings = crossing.check(params, h)
    folder.mkdir(parents=True, exist_ok=True)
    reports.mkdir(parents=True, exist_ok=True)
    text.write_text(report.as_text(h, spans_clear))
    problems = h.problems + spans_clear.problems
    if problems:
        data.unlink(missing_ok=True)
        raise HarnessError("harness check failed, see " + str(text) + ":\n  " + "\n  ".join(problems))
    progress.note("harness: WireViz drawings, and pictures of the routes")
    written = drawing.write(h, catalog, folder)
    for pic, path in zip(picture.PICTURES, pictures):
        picture.draw(params, h, parts, pic, path)
    _keep_only(folder, written + pictures + [data])
    document = report.as_json(h, spans_clear)
    data.write_text(json.dumps(document, indent=1))
    cache.record("harness-checks", checks_key)
    cache.record("harness", drawings_key)
    return _bom(document)


def _bom(document: dict) -> list[tuple[str, float, str]]:
    return [(b["key"], b["per_head"], b["for"]) for b in document["bom"]]


def _keep_only(folder: Path, written: list[Path]) -> None:
    """Remove what an earlier build left in the folder that this one did not write."""
    for stale in folder.iterdir():
        if stale.is_file() and stale not in written:
            stale.unlink()
