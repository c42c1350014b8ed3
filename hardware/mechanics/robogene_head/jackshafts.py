# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The jackshafts of the assembly, found from the parts' data (not their names), for the bearing checks.

A jackshaft is a machined part marked `turning` (a shaft turning in bearings of its own link) that is the journal of
ball bearings whose housing stands on the same link (fits.seats). What turns with it is the shaft and every other part
of its link that touches it (the coupling and the pulley clamped on it, their set screws: surfaces within
clearances.fit_tolerance) and the screws that touch those (the coupling's), the bearings left out: a bearing's
inner ring turns, its outer ring stands. Everything else on
the link stands with the housing. The drive that turns it is the chain joint whose gearhead (`<joint>_gearhead`, the
drive stack's name for it) lies on the shaft's axis; its pulley is the purchased pulley among the parts that turn."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from robogene_head_model.params import CHAIN_JOINTS, HeadParameters

from . import fits, geom, kinematics

ON_AXIS = 1e-3     # mm: a gearhead's axis this close to the shaft's is on it
FASTENERS = ("screw", "set_screw")


@dataclass
class Jackshaft:
    shaft: str                 # the turning part's name
    housing: str               # the part its bearings' outer rings sit in
    link: str
    bearings: list[str]        # bearing part names, along the axis
    joint: str | None          # the chain joint whose gearhead drives it (None: no gearhead on its axis)
    pulley: str | None         # the purchased pulley that turns with it
    turning: list[str]         # the shaft and what touches it (bearings left out)
    origin: np.ndarray         # a point of the axis (world, mm)
    axis: np.ndarray           # unit vector (world)

    def along(self, point: np.ndarray) -> float:
        """A world point's place along the axis from origin (mm)."""
        return float(np.dot(np.asarray(point) - self.origin, self.axis))


def frame(params: HeadParameters, part, poses: dict | None = None) -> np.ndarray:
    """A part's design frame in the world at the zero pose (4x4, mm)."""
    poses = poses if poses is not None else kinematics.link_poses(params, {})
    return geom.part_frame(poses, part)


def _kind(params: HeadParameters, part) -> str:
    catalog = params.root.node("purchased")
    if part.kind != "purchased" or not catalog.has(part.design):
        return ""
    return params.purchased(part.design).text("kind")


def _touching(params: HeadParameters, shaft, candidates: list) -> list:
    """The candidates whose surfaces come within clearances.fit_tolerance of `shaft`."""
    tol = params.geometry("clearances").num("fit_tolerance", positive=True)
    lo, hi = geom.exact_bounds(shaft.shape)
    out = []
    for part in candidates:
        b0, b1 = geom.exact_bounds(part.shape)
        if np.any(b0 > hi + tol) or np.any(b1 < lo - tol):
            continue
        if geom.distance(part.shape, shaft.shape) <= tol:
            out.append(part)
    return out


def _driving_joint(params: HeadParameters, by_name: dict, poses: dict, origin, axis) -> str | None:
    for joint in CHAIN_JOINTS:
        gear = by_name.get(f"{joint}_gearhead")
        if gear is None:
            continue
        m = frame(params, gear, poses)
        if np.linalg.norm(np.cross(m[:3, 2], axis)) > 1e-6:
            continue
        d = m[:3, 3] - origin
        if np.linalg.norm(d - np.dot(d, axis) * axis) <= ON_AXIS:
            return joint
    return None


def find(params: HeadParameters, parts: list, seats: dict | None = None) -> list[Jackshaft]:
    """Every jackshaft of the parts, in the order their shafts appear."""
    seats = seats if seats is not None else fits.seats(params, parts)
    by_name = {p.name: p for p in parts}
    poses = kinematics.link_poses(params, {})
    groups: dict[str, list[str]] = {}
    for name, seat in seats.items():
        shaft, housing = by_name[seat.journal], by_name[seat.housing]
        if shaft.turning and shaft.link == housing.link:
            groups.setdefault(shaft.name, []).append(name)
    out = []
    for shaft_name in [p.name for p in parts if p.name in groups]:
        shaft = by_name[shaft_name]
        first = frame(params, by_name[groups[shaft_name][0]], poses)
        origin, axis = first[:3, 3], first[:3, 2]
        bearings = sorted(groups[shaft_name], key=lambda b: float(np.dot(frame(params, by_name[b], poses)[:3, 3] - origin, axis)))
        housing = seats[bearings[0]].housing
        others = [p for p in parts if p.link == shaft.link and p.name != shaft.name and p.name != housing
                  and _kind(params, p) != "bearing"]
        turning = [shaft] + _touching(params, shaft, others)
        # the screws of what turns turn with it (a screw cannot join what turns to what stands)
        for part in [p for p in turning[1:]]:
            rest = [p for p in others if p not in turning and _kind(params, p) in FASTENERS]
            turning += [p for p in _touching(params, part, rest) if p not in turning]
        pulleys = [p.name for p in turning if _kind(params, p) == "pulley"]
        out.append(Jackshaft(shaft.name, housing, shaft.link, bearings,
                             _driving_joint(params, by_name, poses, origin, axis),
                             pulleys[0] if len(pulleys) == 1 else None, [p.name for p in turning], origin, axis))
    return out
