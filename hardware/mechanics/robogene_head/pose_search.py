# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Gravity torque and inertia about each joint axis, for many poses at once, and their worst case over the whole
range of motion.

The links' mass properties (massprops) are moved by the same kinematic tree as the CAD and the URDF, for a batch of
poses at a time. The worst case is searched over every chain joint's full range, all joints together: a coarse
grid gives the starting poses; from each, a pattern search over every pair of joints (a small grid around the
current pose, shrinking to REFINE_DEG) climbs ridges that run across two joints, and a dense sweep of each joint's
whole range alone catches a better maximum elsewhere along it; the two alternate until neither improves the value.
The neck base stands upright: gravity is -z of the neck_base frame."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from robogene_head_model.params import CHAIN_JOINTS, HeadParameters

from .massprops import MassProps

GRAVITY = 9.80665                  # m/s^2, along -z of the neck base
GRID_SAMPLES = 5                   # per joint, for the starting poses
SWEEP_STEP_DEG = 0.1               # resolution of the one-joint sweeps
REFINE_DEG = 0.005                 # the pattern search stops at this step
PAIR_SAMPLES = 5                   # per joint of a pair, around the current pose
STARTS = 3                         # best grid poses refined per quantity


@dataclass(frozen=True)
class Worst:
    value: float                   # N m (gravity) or kg m^2 (inertia)
    pose: dict[str, float]         # chain angles in degrees where it occurs


def _rotations(axis: np.ndarray, angles_rad: np.ndarray) -> np.ndarray:
    """(N, 3, 3) rotations about a unit axis (Rodrigues)."""
    x, y, z = axis
    k = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    s, c = np.sin(angles_rad)[:, None, None], np.cos(angles_rad)[:, None, None]
    return np.eye(3) + s * k + (1 - c) * (k @ k)


class Chain:
    """The kinematic tree and the links' mass properties in SI units (kg, m, kg m^2), link frames."""

    def __init__(self, params: HeadParameters, props: dict[str, MassProps]):
        self.params = params
        self.joints = [params.joints[name] for name in CHAIN_JOINTS]
        self.limits = np.array([[j.lower, j.upper] for j in self.joints])
        self.props = {link: (mp.mass, mp.com * 1e-3, mp.inertia * 1e-6) for link, mp in props.items() if mp.mass > 0}
        children = {j.parent: [] for j in self.joints}
        for j in self.joints:
            children.setdefault(j.parent, []).append(j.child)
        self.distal = {}
        for j in self.joints:
            below, todo = [], [j.child]
            while todo:
                link = todo.pop()
                below.append(link)
                todo.extend(children.get(link, []))
            self.distal[j.name] = below

    def poses(self, angles_deg: np.ndarray) -> dict[str, tuple[np.ndarray, np.ndarray]]:
        """Per link, (N, 3, 3) rotation and (N, 3) origin in metres, world frame, for (N, 6) chain angles."""
        n = angles_deg.shape[0]
        out = {"neck_base": (np.broadcast_to(np.eye(3), (n, 3, 3)), np.zeros((n, 3)))}
        for k, j in enumerate(self.joints):
            rot, pos = out[j.parent]
            origin = pos + rot @ (np.array(j.origin) * 1e-3)
            out[j.child] = (rot @ _rotations(np.array(j.axis), np.radians(angles_deg[:, k])), origin)
        return out

    def gravity_and_inertia(self, angles_deg: np.ndarray, only: str | None = None) -> dict[str, tuple[np.ndarray, np.ndarray]]:
        """Per joint (or only the one named), for each pose: the torque gravity exerts about the joint axis (N m,
        positive: it turns the joint towards larger angles) and the moment of inertia of everything beyond the joint
        about its axis (kg m^2)."""
        poses = self.poses(angles_deg)
        g = np.array([0.0, 0.0, -GRAVITY])
        out = {}
        for k, j in enumerate(self.joints):
            if only is not None and j.name != only:
                continue
            rot, p = poses[j.child]
            a = rot @ np.array(j.axis)
            torque = np.zeros(angles_deg.shape[0])
            inertia = np.zeros(angles_deg.shape[0])
            for link in self.distal[j.name]:
                if link not in self.props:
                    continue
                m, com, inert = self.props[link]
                r_l, p_l = poses[link]
                d = p_l + r_l @ com - p
                torque += np.einsum("ni,ni->n", a, np.cross(d, m * g))
                own = np.einsum("ni,nij,nj->n", a, r_l @ inert @ np.transpose(r_l, (0, 2, 1)), a)
                lever = np.cross(d, a)
                inertia += own + m * np.einsum("ni,ni->n", lever, lever)
            out[j.name] = (torque, inertia)
        return out

    def worst(self) -> dict[str, tuple[Worst, Worst]]:
        """Per joint: the largest gravity torque magnitude and the largest inertia over the whole range."""
        grid = np.array(np.meshgrid(*[np.linspace(lo, hi, GRID_SAMPLES) for lo, hi in self.limits],
                                    indexing="ij")).reshape(len(self.joints), -1).T
        values = self.gravity_and_inertia(grid)
        out = {}
        for name, (torque, inertia) in values.items():
            found = []
            for which, start_values in ((0, np.abs(torque)), (1, inertia)):
                best = None
                for start in np.argsort(start_values)[::-1][:STARTS]:
                    pose, value = self._ascend(grid[start].copy(), name, which)
                    if best is None or value > best.value:
                        best = Worst(value, {j.name: round(float(q), 3) for j, q in zip(self.joints, pose)})
                found.append(best)
            out[name] = (found[0], found[1])
        return out

    def _ascend(self, pose: np.ndarray, joint: str, which: int) -> tuple[np.ndarray, float]:
        """Climb from `pose` on |gravity torque| (which=0) or inertia (which=1) of `joint`."""
        def f(batch):
            torque, inertia = self.gravity_and_inertia(batch, only=joint)[joint]
            return np.abs(torque) if which == 0 else inertia

        lo, hi = self.limits[:, 0], self.limits[:, 1]
        value = float(f(pose[None, :])[0])

        def take(batch):
            nonlocal pose, value
            vals = f(batch)
            i = int(np.argmax(vals))
            if vals[i] > value * (1 + 1e-12) + 1e-15:
                pose, value = batch[i].copy(), float(vals[i])
                return True
            return False

        n = len(self.joints)
        for _ in range(50):
            improved = False
            for k in range(n):                      # each joint's whole range
                sweep = np.linspace(lo[k], hi[k], int(math.ceil((hi[k] - lo[k]) / SWEEP_STEP_DEG)) + 1)
                batch = np.repeat(pose[None, :], sweep.size, axis=0)
                batch[:, k] = sweep
                improved |= take(batch)
            step = float(np.max(hi - lo)) / 8
            while step >= REFINE_DEG:               # pairs of joints, around the pose
                moved = False
                offsets = np.linspace(-step, step, PAIR_SAMPLES)
                for a in range(n):
                    for b in range(a + 1, n):
                        da, db = np.meshgrid(offsets, offsets, indexing="ij")
                        batch = np.repeat(pose[None, :], da.size, axis=0)
                        batch[:, a] += da.ravel()
                        batch[:, b] += db.ravel()
                        moved |= take(np.clip(batch, lo, hi))
                improved |= moved
                if not moved:
                    step /= 2
            if not improved:
                break
        return pose, value
