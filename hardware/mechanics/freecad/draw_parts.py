# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""FreeCAD GUI macro: one TechDraw drawing (PDF + SVG) per machined part, all in one FreeCAD session.

Run as `freecad draw_parts.py` under xvfb-run (robogene_head/freecad.py does this): TechDraw exports
pages only with its GUI loaded. The job (JSON) is in the file named by ROBOGENE_FC_JOB; the macro appends
one line per finished part to the job's progress file and writes a JSON report, then ends the process
itself (FreeCAD's GUI would otherwise wait for a user)."""
import json
import os
import sys
import traceback

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def draw_one(entry: dict) -> dict:
    import FreeCAD
    import techdraw_page
    doc = FreeCAD.newDocument("Drawing")
    page = None
    try:
        page = techdraw_page.PartPage(doc, entry)
        layout = page.layout()
        dims = page.dimension()
        page.annotate(layout)
        page.draw_lines()
        page.export()
        return {"name": entry["name"], "pdf": os.path.basename(entry["pdf"]), "svg": os.path.basename(entry["svg"]),
                "sheet": layout.sheet.name, "scale": layout.scale, "views": page.view_centres(), "dimensions": dims}
    finally:
        FreeCAD.closeDocument(doc.Name)
        if page is not None:
            page.close()


def main() -> int:
    with open(os.environ["ROBOGENE_FC_JOB"]) as fh:
        job = json.load(fh)
    import FreeCAD
    # before TechDrawGui loads: hole centre marks on the exported page too (default: screen only)
    FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Mod/TechDraw/Decorations").SetBool("PrintCenterMarks", True)
    # TechDraw's own hidden lines with no pen (the style is the preference + 1: -1 is Qt::NoPen): their 0.4 mm
    # hairline dash prints solid. line_overlay draws them instead, from the same hidden-line removal.
    FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Mod/TechDraw/General").SetInt("HiddenLine", -1)
    import FreeCADGui  # noqa: F401  (the GUI side must be up before TechDraw computes views)
    import TechDrawGui  # noqa: F401
    report = {"freecad": ".".join(FreeCAD.Version()[:3]), "drawings": []}
    status = 0
    with open(job["progress"], "a") as progress:
        for entry in job["drawings"]:
            try:
                result = draw_one(entry)
            except Exception:
                result = {"name": entry["name"], "error": traceback.format_exc(limit=4)}
                status = 1
            report["drawings"].append(result)
            progress.write(("failed " if "error" in result else "drawn ") + entry["name"] + "\n")
            progress.flush()
    tmp = job["report"] + ".tmp"
    with open(tmp, "w") as fh:
        json.dump(report, fh, indent=1)
    os.replace(tmp, job["report"])
    return status


try:
    code = main()
except BaseException:
    # FreeCAD's GUI swallows stderr: leave the traceback beside the job for the driver to show.
    with open(os.environ.get("ROBOGENE_FC_JOB", "draw_parts") + ".error", "w") as fh:
        fh.write(traceback.format_exc())
    code = 2
os._exit(code)
