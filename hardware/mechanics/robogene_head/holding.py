# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""What holds each joint when the power goes: the holding element of its drive (drives.<joint>.brake, a purchased
part of kind brake), as torque at the joint.

A power-off brake on the motor's rear shaft holds the joint with its static torque times the drive's reduction N.
The gear train's friction would help it hold (gravity back-drives the gearhead, whose losses then oppose the load),
but no catalogue gives a planetary gearhead's back-driving efficiency, so the brake gets no credit for it: it holds
    at_joint = static torque x N.
The same brake is also the torque limit of the drive train when it stops a moving head (the power fails mid-move)
or someone turns the unpowered head by hand: the joint slips the brake at about static torque x N / eta (eta, the
gearhead's forward efficiency, as the estimate of its back-driving losses, which are larger; the estimate is the
torque the gearhead sees before the brake slips). That must stay within the gearhead's continuous rating (times the
belt stage behind it), or a brake strong enough to hold is also strong enough to break the gearhead."""
from __future__ import annotations

from dataclasses import dataclass

from robogene_head_model import drive_limits
from robogene_head_model.params import HeadParameters


@dataclass(frozen=True)
class Holding:
    joint: str
    part: str                  # purchased key of the brake; "" where the drive has none
    static_mNm: float          # the brake's static torque at the motor shaft
    at_joint_Nm: float         # what it holds at the joint: static torque x N
    slip_Nm: float             # the joint torque that slips it through the gear train: at_joint / eta
    gearhead_rating_Nm: float  # the gearhead's continuous rating, at the joint

    @property
    def present(self) -> bool:
        return bool(self.part)

    @property
    def protects_gearhead(self) -> bool:
        return self.slip_Nm <= self.gearhead_rating_Nm


def holding(params: HeadParameters, joint: str) -> Holding:
    drive = params.drive(joint)
    gear = params.purchased(drive.text("gearhead"))
    rating = gear.num("continuous_torque_Nm", positive=True) * drive_limits.belt_ratio(params, joint)
    if not drive.has("brake"):
        return Holding(joint, "", 0.0, 0.0, 0.0, rating)
    key = drive.text("brake")                     # a purchased brake: the parameter file's loader checks the kind
    static = params.purchased(key).num("static_torque_mNm", positive=True)
    at_joint = static * 1e-3 * drive_limits.reduction(params, joint)
    eta = gear.num("efficiency", positive=True, maximum=1.0)
    return Holding(joint, key, static, at_joint, at_joint / eta, rating)


def rotor_inertia(params: HeadParameters, joint: str) -> float:
    """kg m^2 the brake adds to the motor's rotor (its hub and friction disc turn with the shaft); 0 without one."""
    drive = params.drive(joint)
    if not drive.has("brake"):
        return 0.0
    return params.purchased(drive.text("brake")).num("rotor_inertia_gcm2", positive=True) * 1e-7
