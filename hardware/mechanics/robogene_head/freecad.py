# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Drive freecadcmd (FreeCAD's console, no display) over the package: STEP re-open check and drawings."""
from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess
import tempfile
from pathlib import Path

SCRIPT = Path(__file__).resolve().parents[1] / "freecad" / "check_and_draw.py"
LICENCE = "CERN-OHL-S-2.0"


def script_digest() -> str:
    return hashlib.sha256(SCRIPT.read_bytes()).hexdigest()


def executable() -> str:
    for name in ("freecadcmd", "FreeCADCmd", "freecadcmd-python3"):
        path = shutil.which(name)
        if path:
            return path
    raise RuntimeError("freecadcmd not found: install the packages in tools/setup/apt/hardware.txt")


def run(step_files: list[Path], expected: dict[str, float], machined: list[str], out: Path,
        materials: dict[str, tuple[str, float]] | None = None, solids: dict[str, int] | None = None,
        notes: dict[str, str] | None = None, timeout: float = 600) -> dict:
    """expected: design -> volume (mm^3); the assembly STEP is checked against the sum of its parts'
    volumes, given under the key of its file stem. materials: design -> (name, density kg/m^3)."""
    materials = materials or {}
    solids = solids or {}
    notes = notes or {}
    report = out / "reports" / "freecad-step-check.json"
    report.parent.mkdir(parents=True, exist_ok=True)
    (out / "drawings").mkdir(parents=True, exist_ok=True)
    job = {
        "report": str(report),
        "steps": [{"file": str(p), "volume_mm3": expected[p.stem], "solids": solids.get(p.stem, 1)} for p in step_files],
        "drawings": [{"name": d, "step": str(out / "step" / f"{d}.step"), "out": str(out / "drawings" / f"{d}.svg"),
                      "material": materials.get(d, ("", 0))[0], "density": materials.get(d, ("", 0))[1],
                      "licence": LICENCE, "note": notes.get(d, "")} for d in machined],
    }
    with tempfile.TemporaryDirectory() as home:
        job_path = Path(home) / "job.json"
        job_path.write_text(json.dumps(job))
        env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
        env.update(HOME=home, XDG_CONFIG_HOME=home, XDG_DATA_HOME=home, XDG_CACHE_HOME=home, ROBOGENE_FC_JOB=str(job_path))
        report.unlink(missing_ok=True)
        result = subprocess.run([executable(), str(SCRIPT)], capture_output=True, text=True, env=env,
                                timeout=timeout, cwd=home)
    if not report.exists():
        raise RuntimeError(f"freecadcmd wrote no report (rc {result.returncode}):\n{(result.stdout + result.stderr)[-3000:]}")
    data = json.loads(report.read_text())
    failed = [d for d in data["drawings"] if "error" in d]
    if failed:
        raise RuntimeError("FreeCAD drawing failed: " + "; ".join(f"{d['name']}: {d['error']}" for d in failed))
    return data
