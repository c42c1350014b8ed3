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
torque over the range, margin times over (drive_sizing.margin): `hold_Nm` in the report.

The holding element each drive has (holding.py: a power-off brake on the motor's rear shaft, drives.<joint>.brake)
is then set against that need: `holding_Nm` at the joint, `margin` its ratio to the worst gravity torque. The build
fails (enforce) where a joint would fall and its element holds less than margin times the worst gravity torque, and
where a brake is strong enough to overload its gearhead before it slips (holding.py says why)."""
from __future__ import annotations

import json
from dataclasses import asdict, dataclass

import numpy as np

from robogene_head_model.params import CHAIN_JOINTS, HeadParameters

from . import holding as holding_mod
from .drive_sizing import required_margin, with_payloads
from .massprops import MassProps
from .pose_search import Chain

STEP_DEG = 0.1
BALANCED = 1e-4     # N m: below this, gravity's torque counts as none


class UnpoweredError(RuntimeError):
    """A joint that falls when the power goes, or a brake that would overload its gearhead; the message is the table."""


@dataclass(frozen=True)
class Release:
    joint: str
    case: str            # "loaded" or "bare"
    behaviour: str       # "settles", "falls" or "balanced"
    end_deg: float       # where it comes to rest
    torque_at_end_Nm: float
    worst_gravity_Nm: float
    hold_Nm: float       # what a holding element must carry (0 where the joint does not fall)
    element: str         # the drive's holding element (a purchased key), "" for none
    holding_Nm: float    # what it holds at the joint
    slip_Nm: float       # the joint torque that slips it through the gear train
    gearhead_rating_Nm: float
    required: float      # drive_sizing.margin

    @property
    def margin(self) -> float | None:
        """holding / worst gravity torque, for a joint that falls without its element; None for one that does not."""
        if self.behaviour != "falls" or self.worst_gravity_Nm <= 0:
            return None
        return self.holding_Nm / self.worst_gravity_Nm

    @property
    def held(self) -> bool:
        return self.behaviour != "falls" or self.holding_Nm >= self.hold_Nm

    @property
    def gearhead_safe(self) -> bool:
        return self.slip_Nm <= self.gearhead_rating_Nm

    @property
    def ok(self) -> bool:
        return self.held and self.gearhead_safe


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
    elements = {joint: holding_mod.holding(params, joint) for joint in CHAIN_JOINTS}   # bad data named before the search
    out = []
    for joint in CHAIN_JOINTS:
        found = []
        h = elements[joint]
        for case, p in (("loaded", with_payloads(params, props)), ("bare", props)):
            chain = Chain(params, p)
            behaviour, end, torque = _release(chain, CHAIN_JOINTS.index(joint), joint)
            found.append(Release(joint, case, behaviour, round(end, 3), torque, worst[joint],
                                 margin * worst[joint] if behaviour == "falls" else 0.0,
                                 h.part, h.at_joint_Nm, h.slip_Nm, h.gearhead_rating_Nm, margin))
        order = {"falls": 0, "settles": 1, "balanced": 2}
        out.append(min(found, key=lambda r: (order[r.behaviour], -abs(r.torque_at_end_Nm))))
    return out


def format_table(rows: list[Release]) -> str:
    required = rows[0].required if rows else 0.0
    lines = ["Unpowered: each joint released from rest with no holding element and no friction, then its drive's "
             f"holding element against the worst gravity torque, required margin {required:g}",
             "joint          case    behaviour  at (deg)  torque there  needed | element                   holds  "
             "margin | slips at  gearhead",
             "                                           (N m)         (N m)  |                           (N m)         "
             "|  (N m)     (N m)"]
    for r in rows:
        margin = "     -" if r.margin is None else f"{r.margin:6.2f}"
        flag = "ok" if r.ok else ("FALLS" if not r.held else "OVERLOADS GEARHEAD")
        lines.append(f"{r.joint:<14} {r.case:<7} {r.behaviour:<10} {r.end_deg:8.1f}  {r.torque_at_end_Nm:12.3f}  "
                     f"{r.hold_Nm:6.3f} | {r.element or 'none':<24} {r.holding_Nm:6.3f}  {margin} | "
                     f"{r.slip_Nm:7.3f}  {r.gearhead_rating_Nm:8.3f}  {flag}")
    return "\n".join(lines)


def enforce(rows: list[Release]) -> None:
    bad = [r for r in rows if not r.ok]
    if bad:
        names = ", ".join(f"{r.joint} (" + (f"holds {r.holding_Nm:.3f} of {r.hold_Nm:.3f} N m" if not r.held else
                                             f"slips at {r.slip_Nm:.3f} N m, gearhead {r.gearhead_rating_Nm:.3f}")
                          + ")" for r in bad)
        raise UnpoweredError(f"unpowered: {names}\n" + format_table(rows))


def dumps(rows: list[Release]) -> str:
    return json.dumps({"joints": [dict(asdict(r), margin=r.margin, held=r.held, gearhead_safe=r.gearhead_safe, ok=r.ok)
                                  for r in rows]}, indent=1)
