# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The eyes' angular error budget for stereo, and what the eye drives deliver against it.

Two cameras a baseline B apart, verged on a point at distance Z, see it under the vergence angle g = 2 atan(B / 2Z);
an error dg in vergence moves the fixated depth by dZ = (Z^2 + B^2/4) / B x dg. The budget (eye_accuracy in the
parameter file) allows a depth error at a distance; it gives the vergence error allowed, and half of it per eye
(the two eyes' errors may add). Version (the common gaze direction) carries one eye's error.

What a pan drive leaves uncorrected, measured at the motor (no joint encoder on the pans): its gearhead's backlash
(catalogue, at no load) divided by any stage after it, plus one count of its motor encoder at the joint. Both eyes
at their worst, in opposite directions, make the vergence error; the depth error follows from it."""
from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass

from robogene_head_model import drive_limits
from robogene_head_model.params import HeadParameters

PANS = ("left_eye_pan", "right_eye_pan")


@dataclass(frozen=True)
class EyeBudget:
    distance_mm: float
    depth_error_mm: float             # allowed
    vergence_allowed_deg: float
    per_eye_allowed_deg: float
    backlash_deg: float               # per eye, at the joint
    encoder_count_deg: float          # per eye, at the joint
    per_eye_deg: float                # what the drive leaves: backlash + one count
    vergence_deg: float               # both eyes
    depth_mm: float                   # the depth error that vergence error makes at distance_mm

    @property
    def ok(self) -> bool:
        return self.per_eye_deg <= self.per_eye_allowed_deg


def depth_per_vergence(baseline: float, distance: float) -> float:
    """mm of depth per radian of vergence at a fixation distance (both mm)."""
    return (distance ** 2 + baseline ** 2 / 4) / baseline


def budget(params: HeadParameters) -> EyeBudget:
    node = params.root.node("eye_accuracy")
    z, allowed = node.num("distance", positive=True), node.num("depth_error", positive=True)
    b = params.baseline
    vergence_allowed = math.degrees(allowed / depth_per_vergence(b, z))
    worst = None
    for joint in PANS:
        drive = params.drive(joint)
        gear = params.purchased(drive.text("gearhead"))
        backlash = gear.num("backlash_deg", minimum=0) / drive_limits.belt_ratio(params, joint)
        lines = params.purchased(drive.text("encoder")).num("lines", positive=True)
        count = 360.0 / (4 * lines * drive_limits.reduction(params, joint))
        if worst is None or backlash + count > worst[0] + worst[1]:
            worst = (backlash, count)
    backlash, count = worst
    per_eye = backlash + count
    vergence = 2 * per_eye
    return EyeBudget(z, allowed, vergence_allowed, vergence_allowed / 2, backlash, count, per_eye, vergence,
                     depth_per_vergence(b, z) * math.radians(vergence))


def format_report(e: EyeBudget) -> str:
    verdict = "meets it" if e.ok else "does NOT meet it"
    return (f"Eye accuracy at {e.distance_mm:g} mm: allowed depth error {e.depth_error_mm:g} mm -> vergence error "
            f"{e.vergence_allowed_deg:.3f} deg, {e.per_eye_allowed_deg:.3f} deg per eye.\n"
            f"The pan drives leave {e.per_eye_deg:.3f} deg per eye (backlash {e.backlash_deg:.3f} + one encoder count "
            f"{e.encoder_count_deg:.4f}): vergence error {e.vergence_deg:.3f} deg, depth error {e.depth_mm:.1f} mm; "
            f"the drive {verdict}.")


def dumps(e: EyeBudget) -> str:
    return json.dumps(dict(asdict(e), ok=e.ok), indent=1)
