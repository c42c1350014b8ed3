# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The numbers a motor-control board configuration needs, derived from the parameter file: joint order and
limits of the control board, and per physical joint the motor, the total reduction (gearhead x belt), the
encoder resolutions and what the drive can deliver (drive_limits). Written to build/fab/config/head-joints.json
for the drivers and board configs."""
from __future__ import annotations

from . import drive_limits
from .drive_limits import reduction  # the board-config generator reads it from here too
from .params import CHAIN_JOINTS, HeadParameters


def config(params: HeadParameters) -> dict:
    joints = []
    limits = drive_limits.limits(params)
    for name in CHAIN_JOINTS:
        drive, j = params.drive(name), params.joints[name]
        lines = params.purchased(drive.text("encoder")).num("lines", positive=True)
        ratio = reduction(params, name)
        entry = {"name": name, "min_deg": j.lower, "max_deg": j.upper, "motor": drive.text("motor"),
                 "gearhead": drive.text("gearhead"), "reduction": round(ratio, 6),
                 "motor_encoder_lines": int(lines),
                 "motor_counts_per_joint_degree": round(4 * lines * ratio / 360.0, 6)}
        lim = limits[name]
        entry["drive_limits"] = {"effort_Nm": round(lim.effort, 6), "limited_by": lim.limited_by,
                                 "velocity_rad_s": round(lim.velocity, 6),
                                 "velocity_deg_s": round(lim.velocity_deg_s, 6)}
        if lim.belt_pull:
            entry["drive_limits"]["belt_pull_N"] = round(lim.belt_pull, 6)
        if drive.has("joint_encoder"):
            bits = int(params.purchased(drive.text("joint_encoder")).num("bits", positive=True))
            entry["joint_encoder"] = {"part": drive.text("joint_encoder"), "bits": bits,
                                      "counts_per_degree": round(2 ** bits / 360.0, 6)}
        if drive.has("brake"):
            brake = params.purchased(drive.text("brake"))
            volts, watts = brake.num("voltage", positive=True), brake.num("power_W", positive=True)
            entry["brake"] = {"part": drive.text("brake"), "voltage": volts, "power_W": watts,
                              "coil_current_A": round(watts / volts, 6)}
        joints.append(entry)
    return {
        "source": params.path.name,
        "control_board": [{"index": i, "name": n, "min_deg": lo, "max_deg": hi}
                          for i, (n, (lo, hi)) in enumerate(params.control_limits.items())],
        # How control joints map to motors. The neck is serial (one motor per joint, no tendon differential),
        # so pitch and roll need no decoupling; only the eyes are coupled.
        "couplings": {
            "neck_pitch+neck_roll": {"type": "none", "motors": ["neck_pitch", "neck_roll"]},
            "eyes_version+eyes_vergence": {"type": "version-vergence", "motors": ["left_eye_pan", "right_eye_pan"],
                                           "left_eye_pan": "version + vergence / 2",
                                           "right_eye_pan": "version - vergence / 2"},
        },
        "joints": joints,
    }
