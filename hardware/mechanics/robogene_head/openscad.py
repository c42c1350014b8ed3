# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Render the remixable OpenSCAD printables to STL, with their numbers taken from the parameter file."""
from __future__ import annotations

import math
import os
import subprocess
import tempfile
from pathlib import Path

from robogene_head_model.params import HeadParameters

SCAD_DIR = Path(__file__).resolve().parents[1] / "scad"


def defines(params: HeadParameters) -> dict[str, dict[str, float]]:
    """-D overrides per printable, so the printables follow the head's parameters."""
    eyes, head = params.geometry("eyes"), params.geometry("head")
    r, front = eyes.num("cup_radius"), eyes.num("cup_front_cut")
    cam = params.purchased(params.root.node("cameras").text("model"))
    tilt = params.joints["eyes_tilt"].origin
    return {
        "camera_spacer": {"baseline": params.baseline, "face_d": round(2 * math.sqrt(r * r - front * front), 3),
                          "lens_d": cam.num("lens_diameter")},
        "cable_clip": {},
        "face_plate": {"width": 2 * head.node("floor").num("half_width"), "height": head.node("side_plate").num("height"),
                       "eye_y": tilt[2], "baseline": params.baseline,
                       "edge_inset": head.node("side_plate").num("thickness") / 2,
                       "screw_z": list(head.vec("face_screw_z", 2))},
    }


def sources() -> list[Path]:
    return sorted(SCAD_DIR.glob("*.scad"))


def _scad_value(value) -> str:
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_scad_value(v) for v in value) + "]"
    return f"{value:g}"


def render_stl(scad: Path, values: dict, out: Path, timeout: float = 300) -> None:
    out.parent.mkdir(parents=True, exist_ok=True)
    cmd = ["openscad", "--hardwarnings", "-o", str(out)]
    for key, value in sorted(values.items()):
        cmd += ["-D", f"{key}={_scad_value(value)}"]
    cmd.append(str(scad))
    env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    with tempfile.TemporaryDirectory() as home:
        env["HOME"] = home
        result = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=timeout)
    if result.returncode != 0 or not out.exists() or out.stat().st_size == 0:
        out.unlink(missing_ok=True)
        raise RuntimeError(f"openscad failed on {scad.name} (rc {result.returncode}):\n{result.stderr.strip()[-2000:]}")
