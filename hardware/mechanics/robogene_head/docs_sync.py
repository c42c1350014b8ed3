# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The tables docs/fabricate.md carries from the fabrication package (docs_sync.py --fab DIR --out DIR).

The doc holds copies of the BOM, mass, harness, drive-limit, drive-sizing, unpowered, eye-accuracy and joint-encoder tables
between <!-- NAME:BEGIN --> and <!-- NAME:END --> markers. This script writes each table's body, read from the
package's reports, as the file OUT/NAME; the manifest's `fabrication-tables` generator (codegen/generated-
manifest.yaml) puts them into the doc on `make generate` and compares them on `make check-generated`.
It imports nothing but the standard library, so it runs as a plain script."""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

def mass_table(mass: dict) -> str:
    head, ref = mass["head_above_yaw"], mass["reference"]
    diag = [head["inertia_kgmm2"][i][i] for i in range(3)]
    rows = ["| | this head (above the yaw joint) | reference head | ratio |", "|---|---:|---:|---:|",
            f"| mass (kg) | {head['mass_kg']:.3f} | {ref['mass_kg']:.4f} | {ref['mass_ratio']:.2f} |"]
    for k, axis in enumerate("xyz"):
        rows.append(f"| I{axis}{axis} about the centre of mass (kg mm²) | {diag[k]:.0f} | {ref['inertia_kgmm2_diag'][k]:.1f} | "
                    f"{ref['inertia_ratio_diag'][k]:.2f} |")
    rows += ["", "| link | mass (kg) | centre of mass in the link frame (mm) |", "|---|---:|---|"]
    for link, data in mass["links"].items():
        rows.append(f"| {link} | {data['mass_kg']:.3f} | " + ", ".join(f"{v:.1f}" for v in data["com_mm"]) + " |")
    return "\n".join(rows) + "\n"


def drive_table(joints: dict) -> str:
    rows = ["| joint | motor | gearhead | reduction | effort (N m) | effort set by | top speed (deg/s) | belt pull (N) |",
            "|---|---|---|---:|---:|---|---:|---:|"]
    for j in joints["joints"]:
        lim = j["drive_limits"]
        pull = f"{lim['belt_pull_N']:.0f}" if "belt_pull_N" in lim else "—"
        rows.append(f"| {j['name']} | {j['motor']} | {j['gearhead']} | {j['reduction']:.1f} | {lim['effort_Nm']:.3f} | "
                    f"{lim['limited_by']} | {lim['velocity_deg_s']:.0f} | {pull} |")
    return "\n".join(rows) + "\n"


def harness_table(harness: dict) -> str:
    rows = ["| free span | joints | cut (mm) | cable class | tightest bend R (mm) | allowed R (mm) | twist | limit |",
            "|---|---|---:|---|---:|---:|---:|---:|"]
    for s in harness["spans"]:
        for c in s["checks"]:
            flat = c["twist_unit"] == "edge strain"
            twist = f"{c['twist'] * 100:.2f} %" if flat else f"{c['twist']:.0f} deg/m"
            limit = f"{c['allowed_twist'] * 100:.2f} %" if flat else f"{c['allowed_twist']:.0f} deg/m"
            rows.append(f"| {s['from']} → {s['to']} | {', '.join(s['joints'])} | {s['length_mm']:g} | {c['class']} "
                        f"({c['wires']} wires) | {c['min_bend_radius_mm']:.1f} | {c['allowed_bend_radius_mm']:.1f} | "
                        f"{twist} | {limit} |")
    rows += ["", "| cable | from | to | wires | cut length (mm) |", "|---|---|---|---:|---:|"]
    for c in harness["cables"]:
        rows.append(f"| {c['name']} | {c['from'][0]} {c['from'][1]} | {c['to']} | {len(c['wires'])} | {c['length_mm']:g} |")
    for c in harness["cameras"]:
        rows.append(f"| {c['name']} | camera | head computer | flat | {c['length_mm']:g} (needs {c['required_mm']:.0f}) |")
    return "\n".join(rows) + "\n"


def sizing_table(sizing: dict) -> str:
    rows = ["| joint | worst case | gravity (N m) | inertia (kg m²) | acceleration (deg/s²) | load (N m) | rotor (N m) | "
            "motor capacity (N m) | gearhead capacity (N m) | margin | set by |",
            "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
    for j in sizing["joints"]:
        rows.append(f"| {j['joint']} | {j['case']} | {j['gravity_Nm']:.3f} | {j['inertia_kgm2']:.5f} | "
                    f"{j['accel_deg_s2']:.0f} | {j['load_Nm']:.3f} | {j['rotor_Nm']:.3f} | {j['motor_capacity_Nm']:.3f} | "
                    f"{j['gearhead_capacity_Nm']:.3f} | {j['margin']:.2f} | {j['limited_by']} |")
    return "\n".join(rows) + "\n"


def unpowered_table(data: dict) -> str:
    rows = ["| joint | released from rest, nothing holding it | comes to rest at (deg) | gravity torque there (N m) | "
            "holding needed (N m) | holding element | holds (N m) | margin | slips at (N m) | gearhead rating (N m) |",
            "|---|---|---:|---:|---:|---|---:|---:|---:|---:|"]
    for r in data["joints"]:
        what = {"falls": f"falls onto its stop ({r['case']})", "settles": f"settles, a pendulum ({r['case']})",
                "balanced": "stays: gravity has no torque about it at rest"}[r["behaviour"]]
        margin = "—" if r["margin"] is None else f"{r['margin']:.2f}"
        element = r["element"] or "none"
        slip = f"{r['slip_Nm']:.3f}" if r["element"] else "—"
        rows.append(f"| {r['joint']} | {what} | {r['end_deg']:.1f} | {r['torque_at_end_Nm']:.3f} | {r['hold_Nm']:.3f} | "
                    f"{element} | {r['holding_Nm']:.3f} | {margin} | {slip} | {r['gearhead_rating_Nm']:.3f} |")
    return "\n".join(rows) + "\n"


def torque_table(data: dict) -> str:
    rows = ["| joint | element | at | capacity (N m) | drive's peak there (N m) | margin | what |",
            "|---|---|---|---:|---:|---:|---|"]
    for e in data["elements"]:
        flag = "" if e["ok"] else " **too weak**"
        rated = "" if e.get("rated_Nm") is None else f" (the coupling's rating: {e['rated_Nm']:g} N m)"
        rows.append(f"| {e['joint']} | {e['element']} | {e['at']} | {e['capacity_Nm']:.3f} | {e['peak_Nm']:.3f} | "
                    f"{e['margin']:.2f}{flag} | {e['what']}{rated} |")
    rows += ["", "| joint | continuous (N m) | board's current limit (mA) | kt (mN m/A) | at the limit (N m) | "
             "peak at the gearhead shaft (N m) | set by |", "|---|---:|---:|---:|---:|---:|---|"]
    for j, p in data["peaks"].items():
        rows.append(f"| {j} | {p['continuous_Nm']:.3f} | {p['current_limit_mA']:.0f} | {p['kt_mNm_per_A']:.2f} | "
                    f"{p['current_Nm']:.3f} | {p['at_gearhead_Nm']:.3f} | {p['set_by']} |")
    return "\n".join(rows) + "\n"


def eyes_table(e: dict) -> str:
    """The budget against what the pans leave after calibration (at least, while a counted term is unknown), then
    every term of the worse pan with its source."""
    least = "" if e["per_eye_deg"] is not None else "at least "
    rows = ["| | allowed (budget) | the eye-pan drives, after calibration |", "|---|---:|---:|",
            f"| vergence error (deg) | {e['vergence_allowed_deg']:.4f} | {least}{e['vergence_deg']:.4f} |",
            f"| error per eye, version error (deg) | {e['per_eye_allowed_deg']:.4f} | {least}{e['known_per_eye_deg']:.4f} |",
            f"| depth error at {e['distance_mm']:g} mm (mm) | {e['depth_error_mm']:g} | {least}{e['depth_mm']:.1f} |",
            "", f"| term, per eye at the joint ({e['joint']}) | deg | after calibration | source |", "|---|---:|---|---|"]
    for t in e["terms"]:
        value = "not published" if t["deg"] is None else f"{t['deg']:.4f}"
        rows.append(f"| {t['name']}: {t['what']} | {value} | {'calibrated' if t['repeatable'] else 'counted'} | "
                    f"{t['source']} |")
    return "\n".join(rows) + "\n"


def encoders_table(data: dict) -> str:
    rows = ["| joint | air gap, magnet to IC (mm) | datasheet window (mm) | IC off the magnet's axis (mm) | allowed (mm) |",
            "|---|---:|---:|---:|---:|"]
    for r in data["joints"]:
        gap = f"{r['gap_min_mm']:.2f}" if abs(r["gap_max_mm"] - r["gap_min_mm"]) < 0.005 else \
            f"{r['gap_min_mm']:.2f} to {r['gap_max_mm']:.2f}"
        low, high = r["air_gap_window_mm"]
        rows.append(f"| {r['joint']} | {gap} | {low:g} to {high:g} | {r['ic_off_axis_mm']:.3f} | {r['displacement_mm']:g} |")
    return "\n".join(rows) + "\n"


def blocks(fab: Path) -> dict[str, str]:
    return {"BOM": (fab / "bom" / "robogene-head-bom.md").read_text(),
            "HARNESS": harness_table(json.loads((fab / "harness" / "harness.json").read_text())),
            "MASS": mass_table(json.loads((fab / "reports" / "mass.json").read_text())),
            "DRIVES": drive_table(json.loads((fab / "config" / "head-joints.json").read_text())),
            "SIZING": sizing_table(json.loads((fab / "reports" / "drive-sizing.json").read_text())),
            "UNPOWERED": unpowered_table(json.loads((fab / "reports" / "unpowered.json").read_text())),
            "TORQUE": torque_table(json.loads((fab / "reports" / "torque-path.json").read_text())),
            "EYES": eyes_table(json.loads((fab / "reports" / "eye-accuracy.json").read_text())),
            "ENCODERS": encoders_table(json.loads((fab / "reports" / "joint-encoders.json").read_text()))}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fab", type=Path, required=True, help="the fabrication package (build/fab)")
    ap.add_argument("--out", type=Path, required=True, help="where to write one file per table")
    args = ap.parse_args(argv)
    try:
        tables = blocks(args.fab)
    except FileNotFoundError as exc:
        print(f"docs_sync: {exc.filename}: missing; build the fabrication package first (make fab)", file=sys.stderr)
        return 1
    for name, body in tables.items():
        (args.out / name).write_text(body, encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
