# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Runs inside FreeCAD's freecadcmd (an independent OpenCASCADE build and STEP reader).

1. Re-opens every STEP of the package: it must load, be valid, hold the expected number of solids and the
   volume CadQuery computed (relative tolerance 1e-4).
2. Draws each machined part on an A4 sheet (SVG): three orthographic views projected by TechDraw, overall
   dimensions of every view, a table of the holes read from the part's cylindrical faces, and a title block.

Job description (JSON) in the file named by ROBOGENE_FC_JOB; the report goes where the job says."""
import json
import math
import os
import re
import traceback

import FreeCAD
import Part
import TechDraw

VOLUME_TOLERANCE = 1e-4
A4 = (297.0, 210.0)
# Third-angle views. Each view turns the part so that it is seen from +Z with the drawing's right = +X and
# up = +Y (how TechDraw.projectToSVG lays out a top view), so every view has a known orientation.
# name, rotation rows (model -> view), drawing cell (x, y, width, height)
VIEWS = [
    ("TOP (from +Z; right +X, up +Y)", ((1, 0, 0), (0, 1, 0), (0, 0, 1)), (20.0, 18.0, 125.0, 78.0)),
    ("FRONT (from -Y; right +X, up +Z)", ((1, 0, 0), (0, 0, 1), (0, -1, 0)), (20.0, 110.0, 125.0, 80.0)),
    ("RIGHT (from +X; right +Y, up +Z)", ((0, 1, 0), (0, 0, 1), (1, 0, 0)), (155.0, 110.0, 135.0, 52.0)),
]


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


def _bounds(fragment):
    xs, ys = [], []
    for cmd, args in re.findall(r"([MLAC])\s*([-\d.eE ,]+)", fragment):
        nums = [float(v) for v in re.split(r"[ ,]+", args.strip()) if v]
        if cmd in "ML":
            pairs = list(zip(nums[0::2], nums[1::2]))
        elif cmd == "A":
            pairs = [tuple(nums[i + 5:i + 7]) for i in range(0, len(nums) - 6, 7)]
        else:
            pairs = list(zip(nums[0::2], nums[1::2]))
        for x, y in pairs:
            xs.append(x)
            ys.append(-y)  # the fragment flips y with scale(1,-1)
    num = r'"\s*([-\d.eE]+)\s*"'
    for cx, cy, r in re.findall(r"<circle\s+cx\s*=" + num + r"\s+cy\s*=" + num + r"\s+r\s*=" + num, fragment):
        cx, cy, r = float(cx), -float(cy), float(r)
        xs += [cx - r, cx + r]
        ys += [cy - r, cy + r]
    for cx, cy, rx, ry in re.findall(r"<ellipse\s+cx\s*=" + num + r"\s+cy\s*=" + num + r"\s+rx\s*=" + num +
                                     r"\s+ry\s*=" + num, fragment):
        cx, cy, rx, ry = float(cx), -float(cy), float(rx), float(ry)
        r = max(rx, ry)   # the ellipse may be rotated: bound it by its larger radius
        xs += [cx - r, cx + r]
        ys += [cy - r, cy + r]
    if not xs:
        return None
    return min(xs), max(xs), min(ys), max(ys)


def _holes(shape):
    found = {}
    for face in shape.Faces:
        surf = face.Surface
        if not isinstance(surf, Part.Cylinder):
            continue
        u0, u1, v0, v1 = face.ParameterRange
        u, v = (u0 + u1) / 2, (v0 + v1) / 2
        point = face.valueAt(u, v)
        normal = face.normalAt(u, v)
        axis = surf.Axis
        radial = point - surf.Center
        radial = radial - axis * radial.dot(axis)
        if radial.Length == 0 or normal.dot(radial) >= 0:
            continue  # convex: a shaft or an outside round, not a hole
        d = round(2 * surf.Radius, 2)
        direction = max(("X", abs(axis.x)), ("Y", abs(axis.y)), ("Z", abs(axis.z)), key=lambda t: t[1])[0]
        c = surf.Center
        key = (d, direction)
        # where the bore is: its centre (the face's centre of mass lies on the axis for a full bore)
        com = face.CenterOfMass
        pos = tuple(round(v, 1) for v in (com.x, com.y, com.z))
        found.setdefault(key, set()).add(pos)
    return sorted(((d, a, sorted(p)) for (d, a), p in found.items()), key=lambda t: (-t[0], t[1]))


def _dim_h(x0, x1, y, text):
    return (f'<line x1="{x0:.2f}" y1="{y:.2f}" x2="{x1:.2f}" y2="{y:.2f}" class="dim" marker-start="url(#a)" '
            f'marker-end="url(#a)"/><text x="{(x0 + x1) / 2:.2f}" y="{y - 1.2:.2f}" class="dt" text-anchor="middle">{text}</text>')


def _dim_v(x, y0, y1, text):
    return (f'<line x1="{x:.2f}" y1="{y0:.2f}" x2="{x:.2f}" y2="{y1:.2f}" class="dim" marker-start="url(#a)" '
            f'marker-end="url(#a)"/><text x="{x + 1.5:.2f}" y="{(y0 + y1) / 2:.2f}" class="dt" '
            f'transform="rotate(-90 {x + 1.5:.2f} {(y0 + y1) / 2:.2f})" text-anchor="middle" dy="2.5">{text}</text>')


def draw(entry):
    shape = Part.Shape()
    shape.read(entry["step"])
    views = []
    for title, rows, cell in VIEWS:
        m = FreeCAD.Matrix()
        for i, row in enumerate(rows):
            for j, v in enumerate(row):
                setattr(m, f"A{i + 1}{j + 1}", float(v))
        turned = shape.copy()
        turned.transformShape(m)
        fragment = TechDraw.projectToSVG(turned, FreeCAD.Vector(0, 0, 1))
        b = _bounds(fragment)
        if b is None:
            raise RuntimeError(f"{entry['name']}: empty projection for {title}")
        views.append((title, fragment, b, cell))
    # one scale for all views, from a preferred series, so the sheet can be measured with a ruler
    fit = min(min((c[2] - 16) / max(b[1] - b[0], 1e-6), (c[3] - 16) / max(b[3] - b[2], 1e-6)) for _, _, b, c in views)
    scale = max(s for s in (0.2, 0.25, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0) if s <= fit) if fit >= 0.2 else fit
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{A4[0]}mm" height="{A4[1]}mm" viewBox="0 0 {A4[0]} {A4[1]}">',
           '<defs><marker id="a" viewBox="0 0 10 10" refX="5" refY="5" markerWidth="3" markerHeight="3" orient="auto-start-reverse">'
           '<path d="M0,2 L10,5 L0,8 z"/></marker></defs>',
           '<style>.dim{stroke:#1b4f9c;stroke-width:0.18}.dt{font:2.6px sans-serif;fill:#1b4f9c}'
           '.t{font:3px sans-serif}.h{font:bold 3.5px sans-serif}.s{font:2.4px sans-serif}</style>',
           f'<rect x="5" y="5" width="{A4[0] - 10}" height="{A4[1] - 10}" fill="none" stroke="black" stroke-width="0.5"/>']
    for title, fragment, (x0, x1, y0, y1), (cx, cy, cw, ch) in views:
        w, h = (x1 - x0) * scale, (y1 - y0) * scale
        ox, oy = cx + (cw - w) / 2 - x0 * scale, cy + (ch - h) / 2 - y0 * scale
        stroke = 0.35 / scale
        fragment = fragment.replace('stroke-width="1.0"', f'stroke-width="{stroke:.3f}"')
        out.append(f'<g transform="translate({ox:.3f},{oy:.3f}) scale({scale})">{fragment}</g>')
        left, top = ox + x0 * scale, oy + y0 * scale
        out.append(f'<text x="{cx}" y="{cy - 2}" class="h">{title}</text>')
        out.append(_dim_h(left, left + w, top + h + 6, f"{x1 - x0:.1f}"))
        out.append(_dim_v(left + w + 6, top, top + h, f"{y1 - y0:.1f}"))
    holes = _holes(shape)
    y = 22.0
    out.append(f'<text x="155" y="{y}" class="h">HOLES AND BORES (diameter, count, axis, centre x, y, z)</text>')
    for d, axis, positions in holes[:16]:
        y += 4.2
        where = "; ".join("(" + ", ".join(f"{v:g}" for v in p) + ")" for p in positions[:3])
        more = f" +{len(positions) - 3}" if len(positions) > 3 else ""
        out.append(f'<text x="155" y="{y:.1f}" class="s">&#216;{d:g}  x{len(positions)}  along {axis}  at {where}{more}</text>')
    if entry.get("note"):
        out.append(f'<text x="155" y="{y + 7:.1f}" class="h">NOTE</text>')
        out.append(f'<text x="155" y="{y + 11.5:.1f}" class="s">{entry["note"]}</text>')
    bb = shape.BoundBox
    block = [f"Robogene head  |  {entry['name']}",
             f"material: {entry['material']}   mass: {shape.Volume * entry['density'] * 1e-9 * 1000:.1f} g",
             f"envelope {bb.XLength:.1f} x {bb.YLength:.1f} x {bb.ZLength:.1f} mm   scale {scale:g}:1   units mm",
             "general tolerance ISO 2768-m; break sharp edges 0.3",
             f"source: hardware/head-parameters.yaml  |  {entry['licence']}"]
    out.append('<rect x="155" y="168" width="137" height="37" fill="none" stroke="black" stroke-width="0.35"/>')
    for i, line in enumerate(block):
        out.append(f'<text x="158" y="{174 + 7 * i}" class="{"h" if i == 0 else "t"}">{line}</text>')
    out.append("</svg>")
    with open(entry["out"], "w") as fh:
        fh.write("\n".join(out) + "\n")
    return {"name": entry["name"], "svg": os.path.basename(entry["out"]), "scale": scale, "holes": len(holes)}


def main():
    with open(os.environ["ROBOGENE_FC_JOB"]) as fh:
        job = json.load(fh)
    report = {"freecad": ".".join(FreeCAD.Version()[:3]), "files": [], "drawings": []}
    for entry in job["steps"]:
        report["files"].append(check_step(entry))
    for entry in job["drawings"]:
        try:
            report["drawings"].append(draw(entry))
        except Exception:
            report["drawings"].append({"name": entry["name"], "error": traceback.format_exc(limit=3)})
    with open(job["report"], "w") as fh:
        json.dump(report, fh, indent=1)


main()
