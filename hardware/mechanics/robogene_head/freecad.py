# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Drive FreeCAD over the package: the STEP re-open check in freecadcmd (console, no display), and the
machined-part drawings in FreeCAD's GUI under a virtual X server (TechDraw exports pages only there)."""
from __future__ import annotations

import hashlib
import json
import os
import shutil
import signal
import subprocess
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

FREECAD_DIR = Path(__file__).resolve().parents[1] / "freecad"
CHECK_SCRIPT = FREECAD_DIR / "step_check.py"
DRAW_SCRIPT = FREECAD_DIR / "draw_parts.py"
DRAW_MODULES = ("draw_parts.py", "techdraw_page.py", "view_geometry.py", "dimension_plan.py", "sheet_layout.py",
                "line_overlay.py", "title_block.py", "hole_features.py", "hole_callouts.py",
                "notes_block.py")
LICENCE = "CERN-OHL-S-2.0"
INSTALL_HINT = "install the packages in tools/setup/apt/hardware.txt"


def drawing_digest() -> str:
    """Changes whenever the drawing code changes, so every drawing is redrawn."""
    h = hashlib.sha256()
    for name in DRAW_MODULES:
        h.update((FREECAD_DIR / name).read_bytes())
    return h.hexdigest()


def check_digest() -> str:
    return hashlib.sha256(CHECK_SCRIPT.read_bytes()).hexdigest()


def _which(names: tuple, what: str) -> str:
    for name in names:
        path = shutil.which(name)
        if path:
            return path
    raise RuntimeError(f"{what} not found: {INSTALL_HINT}")


def _fresh_env(home: str, job: Path) -> dict:
    """FreeCAD keeps preferences in $HOME: a throwaway home keeps runs independent of each other."""
    env = dict(os.environ)
    env.update(HOME=home, XDG_CONFIG_HOME=home, XDG_DATA_HOME=home, XDG_CACHE_HOME=home, ROBOGENE_FC_JOB=str(job),
               QTWEBENGINE_DISABLE_SANDBOX="1")   # FreeCAD's GUI refuses to start as root otherwise
    return env


def check_steps(step_files: list[Path], expected: dict[str, float], report: Path,
                solids: dict[str, int] | None = None, timeout: float = 600) -> dict:
    """Re-open each STEP in freecadcmd. expected: file stem -> volume (mm^3) CadQuery computed."""
    solids = solids or {}
    report.parent.mkdir(parents=True, exist_ok=True)
    job = {"report": str(report),
           "steps": [{"file": str(p), "volume_mm3": expected[p.stem], "solids": solids.get(p.stem, 1)} for p in step_files]}
    with tempfile.TemporaryDirectory() as home:
        job_path = Path(home) / "job.json"
        job_path.write_text(json.dumps(job))
        env = _fresh_env(home, job_path)
        env.pop("DISPLAY", None)
        report.unlink(missing_ok=True)
        result = subprocess.run([_which(("freecadcmd", "FreeCADCmd", "freecadcmd-python3"), "freecadcmd"),
                                 str(CHECK_SCRIPT)], capture_output=True, text=True, env=env, timeout=timeout, cwd=home)
    if not report.exists():
        raise RuntimeError(f"freecadcmd wrote no report (rc {result.returncode}):\n{(result.stdout + result.stderr)[-3000:]}")
    return json.loads(report.read_text())


@dataclass
class DrawingJob:
    name: str           # the design (file stem)
    step: Path          # its STEP file, as the package exports it
    material: str = ""
    density: float = 0.0   # kg/m^3, for the mass note
    note: str = ""
    revision: str = ""  # shown in the title block: which geometry this drawing shows
    source: str = ""    # shown in the title block
    threads: list = field(default_factory=list)   # tapped holes (threads.TappedHole.as_dict), design frame


def draw(jobs: list[DrawingJob], folder: Path, on_progress: Callable[[int, int, str], None] | None = None,
         timeout: float | None = None) -> dict:
    """Draw every job's part into folder/<name>.pdf and .svg in one FreeCAD GUI session. Returns the
    session's report: per part the sheet, the scale and every dimension with the value it measures."""
    folder.mkdir(parents=True, exist_ok=True)
    if not jobs:
        return {"drawings": []}
    xvfb = _which(("xvfb-run",), "xvfb-run")
    gui = _which(("freecad", "FreeCAD"), "FreeCAD (GUI)")
    timeout = timeout if timeout is not None else 90 + 45 * len(jobs)
    with tempfile.TemporaryDirectory() as home:
        progress = Path(home) / "progress.txt"
        report = Path(home) / "report.json"
        progress.touch()
        job = {"report": str(report), "progress": str(progress), "drawings": [
            {"name": j.name, "step": str(j.step.resolve()), "pdf": str((folder / f"{j.name}.pdf").resolve()),
             "svg": str((folder / f"{j.name}.svg").resolve()), "material": j.material, "density": j.density,
             "note": j.note, "licence": LICENCE, "revision": j.revision or "-",
             "source": j.source or f"step/{j.name}.step", "threads": j.threads} for j in jobs]}
        job_path = Path(home) / "job.json"
        job_path.write_text(json.dumps(job))
        log = Path(home) / "freecad.log"
        with open(log, "w") as out:
            proc = subprocess.Popen([xvfb, "-a", "-s", "-screen 0 1280x1024x24", gui, str(DRAW_SCRIPT)],
                                    stdout=out, stderr=subprocess.STDOUT, env=_fresh_env(home, job_path), cwd=home,
                                    start_new_session=True)
            seen = 0
            deadline = time.monotonic() + timeout
            while True:
                done = proc.poll() is not None
                lines = progress.read_text().splitlines()
                for i in range(seen, len(lines)):
                    if on_progress:
                        on_progress(i, len(jobs), lines[i])
                seen = len(lines)
                if done:
                    break
                if time.monotonic() > deadline:
                    os.killpg(proc.pid, signal.SIGKILL)   # xvfb-run, Xvfb and FreeCAD: the whole session
                    proc.wait()
                    raise RuntimeError(f"FreeCAD drawing session timed out after {timeout:.0f} s "
                                       f"({seen} of {len(jobs)} parts drawn)")
                time.sleep(0.2)
        error = Path(str(job_path) + ".error")
        if not report.exists():
            detail = error.read_text() if error.exists() else log.read_text()[-3000:]
            raise RuntimeError(f"FreeCAD (GUI) wrote no drawing report (rc {proc.returncode}):\n{detail}")
        data = json.loads(report.read_text())
    failed = [d for d in data["drawings"] if "error" in d]
    if failed:
        raise RuntimeError("FreeCAD drawing failed: " + "; ".join(f"{d['name']}: {d['error']}" for d in failed))
    return data
