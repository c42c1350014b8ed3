# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Each chain joint's drive train and the torque and speed it can deliver at the joint. The numbers come from the
catalogue data of the motors and gearheads under `purchased:` in the parameter file.

A drive is a motor, then a gearhead, then, on neck_yaw and eyes_tilt only, a belt stage:
  belt      = joint_teeth / motor_teeth of pulleys.yaw or pulleys.tilt (1 without a belt)
  reduction = gearhead ratio x belt
  kt        = voltage / no-load speed (rad/s) of the motor                                 [N m/A]
  motor     = min(motor continuous_torque_mNm / 1000, kt x the board's current limit)     [N m, at the motor]
  effort    = min(motor x gearhead ratio x efficiency, gearhead continuous_torque_Nm) x belt
                                                                                           [N m, continuous]
  velocity  = motor no_load_speed_rpm / reduction                                          [at the joint]
The board's current limit (motor_control.joints.<joint>.current_limit, mA per motor) caps the motor's torque: a limit
below the motor's continuous current takes away torque the catalogue ratings would give, so the effort is what the
board allows, not what the motor could. kt from the nominal voltage and the no-load speed leaves out the no-load
current's voltage drop, which errs high by a few per cent. The eye pans are driven through the eye board's coupled
version and vergence axes; its firmware holds both pan motors to the smaller of the two axes' limits.
The gearhead's rating limits the torque on its own output shaft, and on a belted joint that shaft carries the
motor pulley, so the rating applies before the belt stage. The belt stage then multiplies it: the joint may see
more torque than the gearhead's rating. The belt stage is taken as lossless, and the belt's own tension rating is
not in the file, so neither limits the effort; belt_pull (the gearhead shaft's torque over the motor pulley's
pitch radius) is reported for checking it. The no-load speed at the motor's 12 V is a bound that the joint does
not reach under load."""
from __future__ import annotations

import math
from dataclasses import dataclass

from .params import CHAIN_JOINTS, HeadParameters

BELTED = {"neck_yaw": "yaw", "eyes_tilt": "tilt"}   # joint -> its pulleys entry
PAN_JOINTS = ("left_eye_pan", "right_eye_pan")
PAN_CONTROL = ("eyes_version", "eyes_vergence")     # the eye board's control joints, one motor per eye


@dataclass(frozen=True)
class DriveLimit:
    joint: str
    motor: str                  # purchased keys
    gearhead: str
    belt: float                 # belt stage ratio (1: none)
    reduction: float            # motor turns per joint turn
    effort: float               # N m at the joint, continuous, within the board's current limit
    velocity: float             # rad/s at the joint, at the motor's no-load speed
    limited_by: str             # "motor", "current limit" or "gearhead": what sets the effort
    belt_pull: float            # N, the belt's working tension at that effort (0: no belt)
    rated: float                # N m at the joint from the catalogue ratings alone (no current limit)
    kt: float                   # N m/A, the motor's torque constant
    current_limit_mA: float     # what the board allows the motor

    @property
    def velocity_deg_s(self) -> float:
        return math.degrees(self.velocity)


def belt_ratio(params: HeadParameters, joint: str) -> float:
    if joint not in BELTED:
        return 1.0
    pulleys = params.geometry("pulleys", BELTED[joint])
    return pulleys.num("joint_teeth", positive=True) / pulleys.num("motor_teeth", positive=True)


def belt_centre(params: HeadParameters, joint: str) -> float:
    """A belt stage's centre distance (mm), as the CAD draws it: the yaw's from the yaw axis to its jackshaft's
    (geometry.yaw_jackshaft.axis, head frame x, y), the tilt's from the tilt axis to its motor's."""
    if joint == "neck_yaw":
        return math.hypot(*params.geometry("yaw_jackshaft").vec("axis", 2))
    tilt, tm = params.joints["eyes_tilt"].origin, params.geometry("head", "tilt_motor")
    return math.hypot(tilt[0] - tm.num("x"), tilt[2] - tm.num("z"))


def _motor_pulley_radius(params: HeadParameters, joint: str) -> float:
    """Pitch radius of the motor pulley in metres."""
    stage = params.geometry("pulleys", BELTED[joint])
    return stage.num("motor_teeth", positive=True) * stage.num("pitch", positive=True) / (2 * math.pi) / 1000.0


def torque_constant(params: HeadParameters, motor_key: str) -> float:
    """N m/A: kt = U / omega0, the motor's nominal voltage over its no-load speed."""
    motor = params.purchased(motor_key)
    return motor.num("voltage", positive=True) / (motor.num("no_load_speed_rpm", positive=True) * 2 * math.pi / 60)


def current_limit(params: HeadParameters, joint: str) -> float:
    """mA per motor that the board allows the joint's motor (the firmware's: rg_board.c)."""
    joints = params.root.node("motor_control").node("joints")
    if joint in PAN_JOINTS:
        return min(joints.node(c).num("current_limit", positive=True) for c in PAN_CONTROL)
    return joints.node(joint).num("current_limit", positive=True)


def reduction(params: HeadParameters, joint: str) -> float:
    gearhead = params.purchased(params.drive(joint).text("gearhead"))
    return gearhead.num("ratio", positive=True) * belt_ratio(params, joint)


def limit(params: HeadParameters, joint: str) -> DriveLimit:
    drive = params.drive(joint)
    motor_key, gear_key = drive.text("motor"), drive.text("gearhead")
    motor, gear = params.purchased(motor_key), params.purchased(gear_key)
    torque = motor.num("continuous_torque_mNm", positive=True) / 1000.0
    speed = motor.num("no_load_speed_rpm", positive=True)
    ratio = gear.num("ratio", positive=True)
    efficiency = gear.num("efficiency", positive=True, maximum=1.0)
    rating = gear.num("continuous_torque_Nm", positive=True)
    belt = belt_ratio(params, joint)
    kt = torque_constant(params, motor_key)
    amps = current_limit(params, joint)
    allowed = min(torque, kt * amps * 1e-3)
    through = allowed * ratio * efficiency
    shaft = min(through, rating)
    pull = shaft / _motor_pulley_radius(params, joint) if joint in BELTED else 0.0
    if through > rating:
        by = "gearhead"
    else:
        by = "motor" if torque <= kt * amps * 1e-3 else "current limit"
    return DriveLimit(joint, motor_key, gear_key, belt, ratio * belt, shaft * belt,
                      speed * 2 * math.pi / 60 / (ratio * belt), by, pull,
                      min(torque * ratio * efficiency, rating) * belt, kt, amps)


def limits(params: HeadParameters) -> dict[str, DriveLimit]:
    return {joint: limit(params, joint) for joint in CHAIN_JOINTS}
