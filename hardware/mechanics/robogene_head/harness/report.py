# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The harness plan as the package's report: a text table of every cable and every free span with its bend and
twist margins and whether its cables clear the parts (reports/harness.txt), and the same as JSON with the harness's
BOM lines (harness/harness.json)."""
from __future__ import annotations

import math

from .clearance import Clearance
from .plan import Harness, bom_lines


def clearance_json(c: Clearance) -> dict:
    return {"ok": c.ok, "enforced": True, "clamp_zone_mm": c.clamp_zone, "problems": c.problems,
            "unresolved": [{"from": a, "to": b, "why": why} for (a, b), why in c.unresolved.items()],
            "known": c.known,
            "clamps": [{"name": k.name, "link": k.link, "nearest": k.nearest, "distance_mm": round(k.distance, 2),
                        "inside": k.inside or None, "standoff_mm": k.standoff, "ok": k.ok} for k in c.clamps],
            "spans": [{"from": s.a, "to": s.b, "poses": s.poses, "bundle_od_mm": round(s.bundle_od, 2),
                       "flat": [{"cable": n, "width_mm": w, "thickness_mm": t} for n, w, t in s.flat],
                       "blocked": [{"part": b.part, "link": b.link, "cable": b.cable, "at_mm": round(b.at_mm, 1),
                                    "pose": b.pose} for b in s.blocked]} for s in c.spans],
            "crossings": [{"first": list(x.first), "second": list(x.second), "depth_mm": round(x.depth_mm, 2),
                           "pose": x.pose} for x in c.crossings]}


def clearance_text(c: Clearance) -> list[str]:
    out = ["", "Span clearance: each free span's cables along its modelled curve, over the same sweep and the joints "
           "near it (harness.near_joints), against every part (touching the clamp's own link within "
           f"{c.clamp_zone:g} mm of a clamp is not counted)",
           f"{'span':<28} {'bundle (mm)':>11} {'flat cables':<26} {'poses':>6} {'parts in the way':<40}"]
    for s in c.spans:
        flats = ", ".join(n for n, _, _ in s.flat) or "-"
        parts = ", ".join(sorted({b.part for b in s.blocked})) or "none"
        out.append(f"{s.a + ' -> ' + s.b:<28} {s.bundle_od:>11.1f} {flats:<26} {s.poses:>6} {parts}")
    out += ["", "Cables against cables: every pair of free spans swept together (their own joints and the joints near "
            "either), both within clamp_zone of clamps on one link not counted: "
            + ("none touch" if not c.crossings else f"{len(c.crossings)} pair(s) touch, below")]
    out += ["", f"{'clamp':<14} {'link':<16} {'held by (nearest standing part)':<36} {'mm':>6}  inside"]
    for k in c.clamps:
        out.append(f"{k.name:<14} {k.link:<16} {k.nearest:<36} {k.distance:>6.1f}  {k.inside or '-'}")
    if c.unresolved:
        out.append("Known blocked, named in harness.unresolved (docs/fabricate.md, \"Wire the head\"):")
        for (a, b), why in c.unresolved.items():
            out.append(f"  {a} -> {b}: {why}")
        out += [f"    {p}" for p in c.known]
    if c.ok:
        others = " (but the spans named above)" if c.unresolved else ""
        out.append(f"OK: every span's cables clear the parts{others} and each other, every clamp is held")
    else:
        out.append("NOT MET (the build stops):")
        out += [f"  {p}" for p in c.problems]
    return out


def as_json(h: Harness, clearance: Clearance | None = None) -> dict:
    return {
        "ok": h.ok,
        "problems": h.problems,
        "cables": [{"name": c.name, "class": c.cls.name, "from": list(c.source), "header": c.source_mpn,
                    "to": c.target, "wires": list(c.wires), "via": list(c.via), "length_mm": c.length} for c in h.cables],
        "cameras": [{"name": c.name, "via": list(c.via), "required_mm": c.required,
                     "length_mm": None if math.isnan(c.length) else c.length} for c in h.cameras],
        "spans": [{"from": s.a, "to": s.b, "joints": list(s.joints), "poses": s.poses, "max_chord_mm": round(s.max_chord, 2),
                   "length_mm": s.length, "cables": s.cables,
                   "checks": [{"class": c.cls, "wires": c.wires, "min_bend_radius_mm": round(c.min_radius, 2),
                               "allowed_bend_radius_mm": round(c.allowed_radius, 2),
                               "worst_pose": {k: round(v, 2) for k, v in c.min_radius_pose.items()},
                               "twist": round(c.twist, 5), "allowed_twist": c.allowed_twist,
                               "twist_unit": "deg/m" if c.allowed_inplane == 0 else "edge strain",
                               "min_inplane_radius_mm": None if math.isinf(c.min_inplane) else round(c.min_inplane, 1),
                               "allowed_inplane_radius_mm": c.allowed_inplane or None}
                              for c in s.checks]} for s in h.spans.values()],
        "span_clearance": clearance_json(clearance) if clearance else None,
        "bom": [{"key": k, "per_head": q, "for": u} for k, q, u in bom_lines(h)],
    }


def as_text(h: Harness, clearance: Clearance | None = None) -> str:
    out = ["Harness: free spans across the joints, checked over every combination of "
           f"{h.spec.sweep_samples} samples per joint of each span's joints", ""]
    out.append(f"{'span':<28} {'joints':<34} {'free':>6} {'class':<14} {'R min':>7} {'allowed':>8} {'twist':>9} {'limit':>8}")
    for s in h.spans.values():
        for c in s.checks:
            unit = "%" if c.allowed_inplane else "deg/m"
            tw, lim = (c.twist * 100, c.allowed_twist * 100) if c.allowed_inplane else (c.twist, c.allowed_twist)
            out.append(f"{s.a + ' -> ' + s.b:<28} {', '.join(s.joints):<34} {s.length:>6g} {c.cls:<14} "
                       f"{c.min_radius:>7.1f} {c.allowed_radius:>8.1f} {tw:>8.2f}{'%' if unit == '%' else ' '} "
                       f"{lim:>7.2f}{'%' if unit == '%' else ' '}")
    out += ["", f"{'cable':<20} {'class':<14} {'from':<26} {'to':<30} {'wires':>5} {'cut (mm)':>9}"]
    for c in h.cables:
        out.append(f"{c.name:<20} {c.cls.name:<14} {c.source[0] + ' ' + c.source[1]:<26} {c.target:<30} "
                   f"{len(c.wires):>5} {c.length:>9g}")
    for c in h.cameras:
        out.append(f"{c.name:<20} {'camera-ffc':<14} {'camera':<26} {'head computer':<30} {1:>5} "
                   f"{c.length:>9g}  (needs {c.required:.0f})")
    out += ["", "OK: every span within its cables' bend radius and twist limits" if h.ok else "FAILED:"]
    out += [f"  {p}" for p in h.problems]
    if clearance:
        out += clearance_text(clearance)
    return "\n".join(out) + "\n"
