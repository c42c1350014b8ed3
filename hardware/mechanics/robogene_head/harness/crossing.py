# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Whether the free spans' cables run into each other: two loops that meet at some pose rub there at every move,
and the one on top no longer hangs as modelled.

Each pair of free spans is swept together: the joints either crosses at harness.sweep_samples angles each (the
angles its own sweep has, so each span's curve is one the plan worked out), the joints near either
(harness.near_joints) at near_samples, each curve carried with its first clamp's link as in the span clearance
check (clearance.py). At each pose the cables' cross-sections are laid along both curves, the round wires as one
bundle and each flat cable as its band (clearance.bundle_od, the same shapes the parts are tested against), and any
piece of one touching a piece of the other is a crossing: the pair, the pose and how deep the two centre lines
come inside the sum of their radii.

Where both cables lie within clamp_zone of clamps on the same link they are tied down to the same part, side by
side as a lab lays them: that is not counted (a camera cable's two loops meet on the cable shelf this way)."""
from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass, field

import fcl
import numpy as np

from robogene_head_model.params import HeadParameters

from .. import kinematics
from . import spans
from .clearance import basis, bundle_od, flat_cables, near_joints, sections
from .plan import Harness, Span, joint_angles, swept_curves
from .segments import piece_distances


@dataclass(frozen=True)
class Crossing:
    first: tuple[str, str]       # the two spans, (clamp A, clamp B)
    second: tuple[str, str]
    depth_mm: float              # how far inside the sum of the two cross-sections' radii the centre lines come
    pose: dict[str, float]

    def text(self) -> str:
        pose = ", ".join(f"{j} {v:+.1f}" for j, v in self.pose.items())
        return (f"spans {self.first[0]} -> {self.first[1]} and {self.second[0]} -> {self.second[1]}: their cables "
                f"run {self.depth_mm:.1f} mm into each other at {pose}")


@dataclass
class _Cable:
    key: tuple[str, str]
    span: Span
    link: str                    # clamp A's: the curve is carried with it
    ends: tuple[str, str]        # the links of clamps A and B
    od: float                    # the round wires' bundle (clearance.bundle_od), 0 without
    flats: tuple                 # (cable, width, thickness) of each flat cable
    own: list                    # (angles, poses) of its own sweep, the order of curves
    curves: list                 # its curve at each pose of that sweep
    grids: list                  # its own joints' sweep angles (plan.joint_angles), in span.joints' order
    unplace: dict = field(default_factory=dict)     # own sweep's index -> the inverse of clamp A's link pose there

    @property
    def radius(self) -> float:
        """Of the smallest circle round its cross-section (the broad phase)."""
        return max([self.od / 2] + [np.hypot(w, t) / 2 for _, w, t in self.flats])


def _cable(params: HeadParameters, h: Harness, key: tuple[str, str], span: Span) -> _Cable:
    a, b = h.spec.clamps[key[0]], h.spec.clamps[key[1]]
    own, curves = swept_curves(params, span, a, b, h.spec.sweep_samples)
    return _Cable(key, span, a.link, (a.link, b.link), bundle_od(span), flat_cables(span), own, curves,
                  [joint_angles(params, j, h.spec.sweep_samples) for j in span.joints])


def _world(params: HeadParameters, cable: _Cable, samples: int, angles: dict, poses: dict):
    """The cable's curve at these joint angles in the neck base's frame: the points and the width directions."""
    index = 0
    for j, values in zip(cable.span.joints, cable.grids):
        index = index * samples + int(np.argmin(np.abs(values - angles[j])))
    curve = cable.curves[index]
    if index not in cable.unplace:
        cable.unplace[index] = np.linalg.inv(cable.own[index][1][cable.link])
    carry = poses[cable.link] @ cable.unplace[index]
    return (curve, curve.points @ carry[:3, :3].T + carry[:3, 3], curve.widths @ carry[:3, :3].T)


def _tied(cable: _Cable, curve, zone: float) -> tuple[np.ndarray, np.ndarray]:
    """Per piece: within zone of clamp A, within zone of clamp B (along the curve)."""
    s = spans.arc_lengths(curve)
    mid = (s[:-1] + s[1:]) / 2
    return mid < zone, cable.span.length - mid < zone


def pair_crossing(params: HeadParameters, first: _Cable, second: _Cable, zone: float, samples: int,
                  near: dict[str, Sequence[float]], link_poses: dict | None = None) -> Crossing | None:
    """The deepest touch of two spans' cables over their sweep together, None if they never touch. link_poses: the
    links' poses by joint angles, kept across pairs (many pairs sweep the same joints)."""
    link_poses = {} if link_poses is None else link_poses
    own = sorted(set(first.span.joints) | set(second.span.joints))
    grid = {j: joint_angles(params, j, samples) for j in own}
    grid.update({j: v for j, v in near.items() if j not in grid})
    worst: Crossing | None = None
    reach = first.radius + second.radius
    for values in itertools.product(*grid.values()):
        angles = {j: float(v) for j, v in zip(grid, values)}
        pose_key = tuple(sorted(angles.items()))
        if pose_key not in link_poses:
            link_poses[pose_key] = kinematics.link_poses(params, angles)
        poses = link_poses[pose_key]
        c1, p1, w1 = _world(params, first, samples, angles, poses)
        c2, p2, w2 = _world(params, second, samples, angles, poses)
        # broad phase: the two curves' bounding spheres, then every piece's centre line against the other's
        m1, m2 = p1.mean(axis=0), p2.mean(axis=0)
        r1, r2 = np.linalg.norm(p1 - m1, axis=1).max(), np.linalg.norm(p2 - m2, axis=1).max()
        if np.linalg.norm(m1 - m2) > r1 + r2 + reach:
            continue
        d = piece_distances(p1, p2)
        close = np.nonzero(d < reach)
        if not len(close[0]):
            continue
        near_a1, near_b1 = _tied(first, c1, zone)
        near_a2, near_b2 = _tied(second, c2, zone)
        for i, j in zip(*close):
            tied = {first.ends[0]} if near_a1[i] else set()
            tied |= {first.ends[1]} if near_b1[i] else set()
            other = {second.ends[0]} if near_a2[j] else set()
            other |= {second.ends[1]} if near_b2[j] else set()
            if tied & other:
                continue
            if not _touch(first, (p1, w1, i), second, (p2, w2, j)):
                continue
            depth = float(reach - d[i, j])
            if worst is None or depth > worst.depth_mm:
                worst = Crossing(first.key, second.key, depth, {k: round(v, 1) for k, v in angles.items()})
    return worst


def _objects(cable: _Cable, points: np.ndarray, widths: np.ndarray, i: int) -> list:
    """The cable's cross-sections along its piece i, placed."""
    p, q = points[i], points[i + 1]
    seg = float(np.linalg.norm(q - p))
    rot = basis(q - p, widths[i])
    return [fcl.CollisionObject(g, fcl.Transform(rot, (p + q) / 2)) for _, g in sections(cable.od, cable.flats, seg)]


def _touch(first: _Cable, at1, second: _Cable, at2) -> bool:
    for x in _objects(first, *at1):
        for y in _objects(second, *at2):
            if fcl.collide(x, y, fcl.CollisionRequest(), fcl.CollisionResult()) > 0:
                return True
    return False


def check(params: HeadParameters, harness: Harness) -> list[Crossing]:
    """Every pair of free spans whose cables touch, with the deepest touch of each."""
    zone = params.root.node("harness").num("clamp_zone", minimum=0)
    samples = harness.spec.sweep_samples
    cables = [_cable(params, harness, key, span) for key, span in harness.spans.items()]
    out, link_poses = [], {}
    for first, second in itertools.combinations(cables, 2):
        near = near_joints(params, tuple(sorted(set(first.span.joints) | set(second.span.joints))))
        found = pair_crossing(params, first, second, zone, samples, near, link_poses)
        if found is not None:
            out.append(found)
    return out
