# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""A cable's free span between two clamps on links that move relative to each other.

The cable leaves clamp A along its direction there and arrives at clamp B along B's direction, with a fixed cut
length L. Its shape is modelled as the cubic Hermite curve between the clamps whose end tangents are scaled so
that the curve is exactly L long: a smooth curve of the right length through the right ends, standing in for the
elastica a real cable takes (which spreads its bending more evenly, so the model errs on the safe side). From the
curve: the smallest bend radius, and the twist, measured by carrying A's face normal along the curve without
turning it about the tangent (a rotation-minimising frame) and comparing it with B's at the far end. The split of
the curvature into the flat cable's own plane (in-plane bending, which a flat cable cannot take) uses the same
carried frame."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

SAMPLES = 241   # points along a span: 0.5 % of its length apart


@dataclass(frozen=True)
class Frame:
    """A clamp in the world: where the cable passes, its direction (unit) and its face normal (unit, across it)."""
    at: np.ndarray
    dir: np.ndarray
    up: np.ndarray


@dataclass(frozen=True)
class Shape:
    length: float            # of the curve (mm)
    min_radius: float        # smallest bend radius along it (mm)
    min_inplane_radius: float  # smallest radius of the bending in the plane of the face (mm)
    twist_deg: float         # rotation about the cable between the ends (deg)


def _hermite(a: Frame, b: Frame, k: float, t: np.ndarray):
    t = t[:, None]
    h00, h10, h01, h11 = 2 * t**3 - 3 * t**2 + 1, t**3 - 2 * t**2 + t, -2 * t**3 + 3 * t**2, t**3 - t**2
    d00, d10, d01, d11 = 6 * t**2 - 6 * t, 3 * t**2 - 4 * t + 1, -6 * t**2 + 6 * t, 3 * t**2 - 2 * t
    e00, e10, e01, e11 = 12 * t - 6, 6 * t - 4, -12 * t + 6, 6 * t - 2
    p = h00 * a.at + h10 * k * a.dir + h01 * b.at + h11 * k * b.dir
    dp = d00 * a.at + d10 * k * a.dir + d01 * b.at + d11 * k * b.dir
    ddp = e00 * a.at + e10 * k * a.dir + e01 * b.at + e11 * k * b.dir
    return p, dp, ddp


def _length(a: Frame, b: Frame, k: float) -> float:
    t = np.linspace(0.0, 1.0, SAMPLES)
    _, dp, _ = _hermite(a, b, k, t)
    speed = np.linalg.norm(dp, axis=1)
    return float(np.sum((speed[1:] + speed[:-1]) / 2) * (t[1] - t[0]))


def tangent_scale(a: Frame, b: Frame, length: float) -> float:
    """The tangent scale k that makes the curve `length` long (the curve grows with k in the range searched).
    Raises ValueError when the clamps are further apart than `length` allows."""
    chord = float(np.linalg.norm(b.at - a.at))
    if length < chord - 1e-9:
        raise ValueError(f"a {length:.1f} mm span cannot reach between clamps {chord:.1f} mm apart")
    lo, hi = 0.0, max(chord, 1.0)
    while _length(a, b, hi) < length:
        hi *= 2
        if hi > 1e6:
            raise ValueError("no tangent scale reaches the span's length")
    if _length(a, b, lo) > length:
        return lo   # even the straightest curve through these ends is longer: take it
    for _ in range(32):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if _length(a, b, mid) < length else (lo, mid)
    return (lo + hi) / 2


@dataclass(frozen=True)
class Curve:
    """The span's modelled curve, sampled: points, unit tangents, and the carried face normal and width direction
    (across a flat cable's width) at each."""
    points: np.ndarray
    tangents: np.ndarray
    normals: np.ndarray
    widths: np.ndarray
    speed: np.ndarray
    second: np.ndarray       # d2p/dt2, for the curvature
    k: float


def curve(a: Frame, b: Frame, length: float, samples: int = SAMPLES) -> Curve:
    """The curve `length` long from A to B, at `samples` points evenly spaced in its parameter."""
    k = tangent_scale(a, b, length)
    t = np.linspace(0.0, 1.0, samples)
    p, dp, ddp = _hermite(a, b, k, t)
    speed = np.linalg.norm(dp, axis=1)
    if np.any(speed < 1e-9):
        raise ValueError("the span's curve stops (its clamps point at each other along one line)")
    tangents = dp / speed[:, None]
    # Rotation-minimising frame by double reflection (Wang et al. 2008), starting from A's face normal.
    normal = a.up - np.dot(a.up, tangents[0]) * tangents[0]
    normal /= np.linalg.norm(normal)
    normals = [normal]
    for i in range(len(p) - 1):
        v1 = p[i + 1] - p[i]
        c1 = np.dot(v1, v1)
        if c1 < 1e-18:
            normals.append(normal)
            continue
        r_l = normal - (2 / c1) * np.dot(v1, normal) * v1
        t_l = tangents[i] - (2 / c1) * np.dot(v1, tangents[i]) * v1
        v2 = tangents[i + 1] - t_l
        c2 = np.dot(v2, v2)
        normal = r_l - (2 / c2) * np.dot(v2, r_l) * v2 if c2 > 1e-18 else r_l
        normal /= np.linalg.norm(normal)
        normals.append(normal)
    normals = np.array(normals)
    return Curve(p, tangents, normals, np.cross(tangents, normals), speed, ddp, k)


def arc_lengths(c: Curve) -> np.ndarray:
    """Distance along the curve from A to each sample (mm)."""
    steps = np.linalg.norm(np.diff(c.points, axis=0), axis=1)
    return np.concatenate([[0.0], np.cumsum(steps)])


def shape(a: Frame, b: Frame, length: float) -> Shape:
    c = curve(a, b, length)
    speed, tangents, normals, ddp = c.speed, c.tangents, c.normals, c.second
    dp = tangents * speed[:, None]
    cross = np.cross(dp, ddp)
    curvature = np.linalg.norm(cross, axis=1) / speed**3
    # Curvature vector = d(tangent)/ds; its component along the face's width direction is in-plane bending.
    kappa_vec = (ddp - np.sum(ddp * tangents, axis=1)[:, None] * tangents) / speed[:, None] ** 2
    inplane = np.abs(np.sum(kappa_vec * c.widths, axis=1))
    end_up = b.up - np.dot(b.up, tangents[-1]) * tangents[-1]
    end_up /= np.linalg.norm(end_up)
    twist = math.degrees(math.atan2(float(np.dot(np.cross(normals[-1], end_up), tangents[-1])),
                                    float(np.dot(normals[-1], end_up))))
    return Shape(_length(a, b, c.k), float(1 / max(curvature.max(), 1e-12)), float(1 / max(inplane.max(), 1e-12)),
                 twist)
