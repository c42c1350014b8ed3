# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Runs inside FreeCAD's freecadcmd (an independent OpenCASCADE build and STEP reader, no display).

Re-opens every STEP of the package: it must load, be valid, hold the expected number of solids and the
volume CadQuery computed (relative tolerance 1e-4). The drawings are made by draw_parts.py in FreeCAD's
GUI, because TechDraw cannot export a page from the console.

Job description (JSON) in the file named by ROBOGENE_FC_JOB; the report goes where the job says."""
import json
import os

import FreeCAD
import Part

VOLUME_TOLERANCE = 1e-4


def check_step(entry):
    result = {"file": os.path.basename(entry["file"]), "ok": False, "problem": ""}
    try:
        shape = Part.Shape()
        shape.read(entry["file"])
    except Exception as exc:  # FreeCAD raises its own Base.FreeCADError types
        result["problem"] = f"cannot read: {exc}"
        return result
    solids = len(shape.Solids)
    volume = sum(s.Volume for s in shape.Solids)
    result.update(valid=shape.isValid(), solids=solids, volume_mm3=round(volume, 4))
    problems = []
    if not shape.isValid():
        problems.append("shape is not valid")
    if solids != entry["solids"]:
        problems.append(f"{solids} solids, expected {entry['solids']}")
    expected = entry["volume_mm3"]
    if abs(volume - expected) > VOLUME_TOLERANCE * max(expected, 1.0):
        problems.append(f"volume {volume:.4f} mm^3, CadQuery computed {expected:.4f}")
    result["problem"] = "; ".join(problems)
    result["ok"] = not problems
    return result


def main():
    with open(os.environ["ROBOGENE_FC_JOB"]) as fh:
        job = json.load(fh)
    report = {"freecad": ".".join(FreeCAD.Version()[:3]), "files": []}
    for entry in job["steps"]:
        report["files"].append(check_step(entry))
    with open(job["report"], "w") as fh:
        json.dump(report, fh, indent=1)


main()
