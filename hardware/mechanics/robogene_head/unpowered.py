# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""What each joint does when the power goes, computed from the same mass properties as the drive sizing.

With the motors unpowered, nothing in this head's drive trains holds a joint: planetary and spur gearheads are
back-drivable (FAULHABER: all of them run in both directions), the motors are coreless (no detent), and the
motor-control boards leave the windings open when unpowered. Friction is left out: no catalogue gives it for
back-driving, so the result is the conservative one. Each joint is released from the rest pose (all joints at 0,
with and without the payloads) and turns the way gravity pushes it, one degree step at a time, until gravity's
torque reverses (it settles there: a pendulum) or it reaches its limit (it falls onto its stop). A joint that falls
needs a holding element (a brake, a counterbalance spring or a self-locking stage) that carries the worst gravity
torque over the range, margin times over (drive_sizing.margin): `hold_Nm` in the report."""
from __future__ import annotations

import json
from dataclasses import asdict, dataclass

import numpy as np

from robogene_head_model.params import CHAIN_JOINTS, HeadParameters

from .drive_sizing import required_margin, with_payloads
from .massprops import MassProps
from .pose_search import Chain

STEP_DEG = 0.1
BALANCED = 1e-4     # N m: below this, gravity's torque counts as none


@dataclass(frozen=True)
class Release:
    joint: str
    case: str            # "loaded" or "bare"
    behaviour: str       # "settles", "falls" or "balanced"
    end_deg: float       # where it comes to rest
    torque_at_end_Nm: float
    worst_gravity_Nm: float
    hold_Nm: float       # what a holding element must carry (0 where the joint does not fall)


def _release(chain: Chain, index: int, joint: str) -> tuple[str, float, float]:
    lo, hi = chain.limits[index]
    sweep = np.arange(lo, hi + STEP_DEG / 2, STEP_DEG)
    batch = np.zeros((sweep.size, len(chain.joints)))
    batch[:, index] = sweep
    torque = chain.gravity_and_inertia(batch)[joint][0]
    start = int(np.argmin(np.abs(sweep)))
    if np.max(np.abs(torque)) < BALANCED:
        return "balanced", 0.0, 0.0
    direction = np.sign(torque[start])
    if abs(torque[start]) < BALANCED:   # an equilibrium at rest: stable only if a nudge either way comes back
        left, right = torque[max(start - 1, 0)], torque[min(start + 1, sweep.size - 1)]
        if right <= 0 <= left:
            return "settles", float(sweep[start]), float(torque[start])
        direction = 1.0 if abs(torque[-1]) >= abs(torque[0]) else -1.0
    i = start
    while 0 <= i + int(direction) < sweep.size and np.sign(torque[i + int(direction)]) in (direction, 0.0):
        i += int(direction)
    at_limit = i in (0, sweep.size - 1) and np.sign(torque[i]) == direction
    return ("falls" if at_limit else "settles"), float(sweep[i]), float(torque[i])


def analyse(params: HeadParameters, props: dict[str, MassProps], worst: dict[str, float]) -> list[Release]:
    """worst: each joint's worst gravity torque over the whole range (drive_sizing), for the holding need."""
    margin = required_margin(params)
    out = []
    for joint in CHAIN_JOINTS:
        found = []
        for case, p in (("loaded", with_payloads(params, props)), ("bare", props)):
            chain = Chain(params, p)
            behaviour, end, torque = _release(chain, CHAIN_JOINTS.index(joint), joint)
            found.append(Release(joint, case, behaviour, round(end, 3), torque, worst[joint],
                                 margin * worst[joint] if behaviour == "falls" else 0.0))
        order = {"falls": 0, "settles": 1, "balanced": 2}
        out.append(min(found, key=lambda r: (order[r.behaviour], -abs(r.torque_at_end_Nm))))
    return out


def format_table(rows: list[Release]) -> str:
    lines = ["Unpowered (no holding element, no friction): each joint released from rest",
             "joint          case    behaviour  at (deg)  torque there (N m)  holding element needed (N m)"]
    for r in rows:
        lines.append(f"{r.joint:<14} {r.case:<7} {r.behaviour:<10} {r.end_deg:8.1f}  {r.torque_at_end_Nm:18.3f}  "
                     f"{r.hold_Nm:28.3f}")
    return "\n".join(lines)


def dumps(rows: list[Release]) -> str:
    return json.dumps({"joints": [asdict(r) for r in rows]}, indent=1)
