# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Drives sized by a check: each joint's drive must deliver the worst-case load with a margin.

For every chain joint, from the links' mass properties (the CAD's, as in the URDF) plus the payloads under
drive_sizing.payloads in the parameter file, in two load cases (with and without the payloads):
  gravity  G = the largest gravity torque about the joint over the whole range of every joint (pose_search)
  inertia  J = the largest moment of inertia beyond the joint about its axis, over the same range
  load     L = G + J x alpha, alpha the joint's acceleration under drive_sizing.accelerations
Each is a worst case of its own, so their sum bounds the load at any pose. The drive (drive_limits: motor, gearhead
of ratio N and efficiency eta, belt stage b) must carry it margin times over, within what the board allows:
  motor     min(continuous torque, kt x current limit) x N b x eta  >=  margin x (L + J_rotor x (N b)^2 x eta x alpha)
  gearhead  continuous rating x b                                    >=  margin x L
The board's current limit (motor_control.joints.<joint>.current_limit; kt as drive_limits derives it) caps the motor's
torque: a limit below the motor's continuous current starves the drive, and the check fails on it as on a small motor.
The motor also accelerates its own rotor (rotor_inertia_gcm2, plus a holding brake's hub and disc where the drive
has one), which the gear train multiplies by the square of the reduction; the gearhead carries the load only.
Gearhead and pulley inertias are left out (a few per cent of the rotor's). Margin is the smaller of the two ratios
capacity / demand; the build fails when it is below drive_sizing.margin."""
from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass

import numpy as np

from robogene_head_model import drive_limits
from robogene_head_model.params import CHAIN_JOINTS, HeadParameters, Node, ParameterError

from . import holding
from .massprops import MassProps, combine
from .pose_search import Chain, Worst


class SizingError(RuntimeError):
    """A drive below its margin; the message is the table."""


@dataclass(frozen=True)
class JointSizing:
    joint: str
    case: str                  # the load case that sets the demand: "loaded" or "bare"
    gravity_Nm: float
    gravity_pose: dict
    inertia_kgm2: float
    inertia_pose: dict
    accel_deg_s2: float
    load_Nm: float             # G + J alpha
    rotor_Nm: float            # the rotor's acceleration torque, seen at the joint
    motor_capacity_Nm: float   # continuous, at the joint
    gearhead_capacity_Nm: float
    motor_margin: float
    gearhead_margin: float
    current_limited: bool      # the board's current limit, not the motor's rating, sets the motor capacity

    @property
    def margin(self) -> float:
        return min(self.motor_margin, self.gearhead_margin)

    @property
    def limited_by(self) -> str:
        if self.motor_margin > self.gearhead_margin:
            return "gearhead"
        return "current limit" if self.current_limited else "motor"


@dataclass(frozen=True)
class SizingReport:
    required: float
    joints: list[JointSizing]

    @property
    def ok(self) -> bool:
        return all(j.margin >= self.required for j in self.joints)

    def failures(self) -> list[JointSizing]:
        return [j for j in self.joints if j.margin < self.required]


def _sizing(params: HeadParameters):
    return params.root.node("drive_sizing")


def required_margin(params: HeadParameters) -> float:
    return _sizing(params).num("margin", minimum=1.0)


def acceleration(params: HeadParameters, joint: str) -> float:
    """deg/s^2 the joint must reach."""
    return _sizing(params).node("accelerations").num(joint, positive=True)


def payloads(params: HeadParameters) -> list[tuple[str, str, MassProps]]:
    """(name, link, mass properties in the link frame) of each budgeted payload: a uniform box."""
    node = _sizing(params)
    listed = node.raw("payloads")
    if not isinstance(listed, list):
        raise ParameterError(f"{params.path}: drive_sizing.payloads: expected a list, got {listed!r}")
    out = []
    for i, entry in enumerate(listed):
        item = Node(entry, f"drive_sizing.payloads[{i}]", str(params.path))
        link = item.text("link")
        if link not in {params.joints[j].child for j in CHAIN_JOINTS}:
            raise item.fail("link", f"{link!r} is not a moving link")
        m = item.num("mass", positive=True)
        a, b, c = item.vec("size")
        if min(a, b, c) <= 0:
            raise item.fail("size", f"expected three positive lengths, got {[a, b, c]}")
        inertia = np.diag([m * (b * b + c * c), m * (a * a + c * c), m * (a * a + b * b)]) / 12
        out.append((item.text("name"), link, MassProps(m, np.array(item.vec("centre")), inertia)))
    return out


def with_payloads(params: HeadParameters, props: dict[str, MassProps]) -> dict[str, MassProps]:
    out = dict(props)
    for _, link, mp in payloads(params):
        out[link] = combine([out[link], mp]) if link in out else mp
    return out


def _rotor_inertia(params: HeadParameters, joint: str) -> float:
    """kg m^2 turning at motor speed: the rotor, and the hub and disc of a brake on its rear shaft."""
    motor = params.purchased(params.drive(joint).text("motor"))
    return motor.num("rotor_inertia_gcm2", positive=True) * 1e-7 + holding.rotor_inertia(params, joint)


def size(params: HeadParameters, props: dict[str, MassProps]) -> SizingReport:
    required = required_margin(params)
    drives = {}
    for joint in CHAIN_JOINTS:   # every number read (and refused by its key) before the search
        drive = params.drive(joint)
        motor_key = drive.text("motor")
        motor, gear = params.purchased(motor_key), params.purchased(drive.text("gearhead"))
        eta = gear.num("efficiency", positive=True, maximum=1.0)
        n = drive_limits.reduction(params, joint)
        accel_deg = acceleration(params, joint)
        alpha = math.radians(accel_deg)
        rated = motor.num("continuous_torque_mNm", positive=True) * 1e-3
        allowed = drive_limits.torque_constant(params, motor_key) * drive_limits.current_limit(params, joint) * 1e-3
        drives[joint] = (accel_deg, alpha, min(rated, allowed) * n * eta,
                         gear.num("continuous_torque_Nm", positive=True) * drive_limits.belt_ratio(params, joint),
                         _rotor_inertia(params, joint) * n * n * eta * alpha, allowed < rated)
    loaded = with_payloads(params, props)
    cases = {"bare": Chain(params, props).worst(), "loaded": Chain(params, loaded).worst()}
    rows = []
    for joint in CHAIN_JOINTS:
        accel_deg, alpha, motor_cap, gear_cap, rotor, starved = drives[joint]
        worst_row = None
        for case, found in cases.items():
            gravity, inertia = found[joint]
            load = gravity.value + inertia.value * alpha
            row = JointSizing(joint, case, gravity.value, gravity.pose, inertia.value, inertia.pose, accel_deg, load,
                              rotor, motor_cap, gear_cap, motor_cap / (load + rotor), gear_cap / load, starved)
            if worst_row is None or row.margin < worst_row.margin:
                worst_row = row
        rows.append(worst_row)
    return SizingReport(required, rows)


def format_table(report: SizingReport) -> str:
    head = ("joint          case    gravity  inertia   accel    load   rotor  demand | motor  gearhead | margin  "
            "limited by")
    units = ("               (worst)  (N m)  (kg m^2) (deg/s^2) (N m)  (N m)  (N m)  | capacity (N m)  |")
    lines = [f"Drive sizing: worst case over the whole range, required margin {report.required:g}", head, units]
    for j in report.joints:
        demand = j.load_Nm if j.limited_by == "gearhead" else j.load_Nm + j.rotor_Nm
        flag = "ok" if j.margin >= report.required else "TOO SMALL"
        lines.append(f"{j.joint:<14} {j.case:<7} {j.gravity_Nm:7.3f} {j.inertia_kgm2:9.5f} {j.accel_deg_s2:7.0f} "
                     f"{j.load_Nm:7.3f} {j.rotor_Nm:7.3f} {demand:7.3f} | {j.motor_capacity_Nm:6.3f} "
                     f"{j.gearhead_capacity_Nm:8.3f} | {j.margin:6.2f}  {j.limited_by} {flag}")
    return "\n".join(lines)


def report_json(report: SizingReport) -> dict:
    return {"required_margin": report.required, "ok": report.ok,
            "joints": [dict(asdict(j), margin=j.margin, limited_by=j.limited_by, ok=j.margin >= report.required)
                       for j in report.joints]}


def enforce(report: SizingReport) -> None:
    if not report.ok:
        names = ", ".join(f"{j.joint} ({j.margin:.2f})" for j in report.failures())
        raise SizingError(f"drives below the required margin {report.required:g}: {names}\n" + format_table(report))


def dumps(report: SizingReport) -> str:
    return json.dumps(report_json(report), indent=1)
