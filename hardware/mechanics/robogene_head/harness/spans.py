# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""A cable's free span between two clamps on links that move relative to each other.

The cable leaves clamp A along its direction there and arrives at clamp B along B's direction, with a fixed cut
length L. It takes the shape of least bending energy among all curves of that length between those ends: the
elastica, which is what a flexible cable with no other load settles into. The curve is modelled as SEGMENTS
straight pieces of equal length, turning from clamp A's direction and to clamp B's over half a piece, and relaxed
by minimising the bending energy (the squared turns over the lengths they are taken over) with its far end held on
clamp B; the first guesses are cubic Hermite curves through the same ends (see curves()).
From the curve: the smallest bend radius, and the twist, measured by carrying A's face normal along the curve
without turning it about the cable (a rotation-minimising frame) and comparing it with B's at the far end. The
split of the curvature into the flat cable's own plane (in-plane bending, which a flat cable cannot take) uses the
same carried frame."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

SAMPLES = 241      # points along the Hermite first guess: 0.5 % of its length apart
SEGMENTS = 48      # straight pieces of the modelled cable
TOLERANCE = 1e-3   # mm: how far the relaxed curve's end may lie from clamp B
NEWTON_STEPS = 60  # at most
MAX_TURN = 0.3     # rad: the most a Newton step turns any piece
GIVE = 1e-9
GUESS_SAMPLES, GUESS_STEPS = 61, 12   # the first guess's length: to within about 0.1 %
PAY_OUT = (0.1, 0.25, 0.45, 0.7, 1.0)   # shares of the slack the cable is relaxed at in turn


class SpanError(ValueError):
    """A span's cable cannot be laid between its clamps; pose: the index of the pose where, when it is one pose's."""

    def __init__(self, message: str, pose: int | None = None):
        super().__init__(message)
        self.pose = pose


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
    p = h00 * a.at + h10 * k * a.dir + h01 * b.at + h11 * k * b.dir
    dp = d00 * a.at + d10 * k * a.dir + d01 * b.at + d11 * k * b.dir
    return p, dp


def _length(a: Frame, b: Frame, k: float, samples: int = SAMPLES) -> float:
    t = np.linspace(0.0, 1.0, samples)
    _, dp = _hermite(a, b, k, t)
    speed = np.linalg.norm(dp, axis=1)
    return float(np.sum((speed[1:] + speed[:-1]) / 2) * (t[1] - t[0]))


def tangent_scale(a: Frame, b: Frame, length: float, samples: int = SAMPLES, steps: int = 32) -> float:
    """The tangent scale k that makes the Hermite curve `length` long (the curve grows with k in the range searched),
    to `steps` halvings, its length summed over `samples` points. Raises ValueError when the clamps are further apart
    than `length` allows."""
    chord = float(np.linalg.norm(b.at - a.at))
    if length < chord - 1e-9:
        raise ValueError(f"a {length:.1f} mm span cannot reach between clamps {chord:.1f} mm apart")
    lo, hi = 0.0, max(chord, 1.0)
    while _length(a, b, hi, samples) < length:
        hi *= 2
        if hi > 1e6:
            raise ValueError("no tangent scale reaches the span's length")
    if _length(a, b, lo, samples) > length:
        return lo   # even the straightest curve through these ends is longer: take it
    for _ in range(steps):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if _length(a, b, mid, samples) < length else (lo, mid)
    return (lo + hi) / 2


def _first_guess(a: Frame, b: Frame, length: float, segments: int) -> np.ndarray:
    """The pieces' directions along the Hermite curve of about the span's length, cut into equal lengths (a first
    guess: the relaxation holds the curve's end on clamp B, so its length need not be exact)."""
    k = tangent_scale(a, b, length, GUESS_SAMPLES, GUESS_STEPS)
    p, _ = _hermite(a, b, k, np.linspace(0.0, 1.0, 4 * SAMPLES))
    s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(p, axis=0), axis=1))])
    at = np.linspace(0.0, s[-1], segments + 1)
    nodes = np.column_stack([np.interp(at, s, p[:, i]) for i in range(3)])
    d = np.diff(nodes, axis=0)
    norms = np.linalg.norm(d, axis=1)
    if np.any(norms < 1e-12):
        raise ValueError("the span's curve stops (its clamps point at each other along one line)")
    return d / norms[:, None]


def _tangent_bases(d: np.ndarray) -> np.ndarray:
    """Two unit vectors across each direction (poses x pieces x 3 -> poses x pieces x 3 x 2)."""
    helper = np.where(np.abs(d[..., :1]) < 0.9, np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0]))
    u = np.cross(d, helper)
    u /= np.linalg.norm(u, axis=-1, keepdims=True)
    return np.stack([u, np.cross(d, u)], axis=-1)


def _relax(starts: np.ndarray, ends: np.ndarray, targets: np.ndarray, lengths: np.ndarray, start: np.ndarray):
    """The pieces' directions of least bending energy, for every pose's pair of clamps at once (starts, ends: the
    clamps' unit directions, targets: B's place less A's, each poses x 3; start: the first guesses, poses x pieces x
    3; lengths: each pose's cable length), the far end on clamp B. Returns the directions and how far each pose's
    curve ends from clamp B (mm).

    The clamps hold the cable's direction at its ends: the turn from clamp A's direction to the first piece is taken
    over half a piece, as is the turn from the last piece to B's (the nodes are the pieces' ends). With the pieces'
    unit directions d[0..n-1] of length h, and A, B the clamps' directions, the bending energy is
      E = (2/h) |d[0] - A|^2 + sum |d[j+1] - d[j]|^2 / h + (2/h) |B - d[n-1]|^2,
    under the constraint h * sum d = (B's place - A's place). On unit vectors E is, up to a constant,
    -(2/h) sum d[j].d[j+1] with d[-1] = 2A and d[n] = 2B. Newton's method on the Lagrangian, every piece moved in
    the plane across it and renormalised (every pose's small system solved together); a step turns no piece by more
    than MAX_TURN, which keeps the first steps from a rough guess from overshooting."""
    poses, n = start.shape[:2]
    h = (lengths / n)[:, None, None]     # each pose's piece length, broadcast over pieces and coordinates
    before, after = 2 * starts[:, None, :], 2 * ends[:, None, :]
    d = start.copy()
    size = 2 * n + 3
    lam = np.zeros((poses, 3))
    rows = np.arange(n)
    k = np.zeros((poses, size, size))
    # A taut span cannot lengthen along its chord: the constraint block gets a small give so the system stays
    # solvable there (the step it leaves along that direction is of the order of the give).
    k[:, 2 * n:, 2 * n:] = -GIVE * np.eye(3)
    for _ in range(NEWTON_STEPS):
        t = _tangent_bases(d)                                          # poses x pieces x 3 x 2
        padded = np.concatenate([before, d, after], axis=1)
        grad = (-2 / h) * (padded[:, :-2] + padded[:, 2:]) + h * lam[:, None, :]   # Euclidean, of the Lagrangian
        g = np.einsum("pfk,pfkc->pfc", grad, t)                        # ... across each piece
        c = h[:, 0] * d.sum(axis=1) - targets
        diag = -np.sum(d * grad, axis=2)                               # the sphere's curvature term
        for axis in range(2):
            k[:, 2 * rows + axis, 2 * rows + axis] = diag
        off = (-2 / h[:, :1, None]) * np.einsum("pfkc,pfke->pfce", t[:, :-1], t[:, 1:])   # piece f with f + 1
        for i in range(2):
            for j in range(2):
                k[:, 2 * rows[:-1] + i, 2 * rows[1:] + j] = off[:, :, i, j]
                k[:, 2 * rows[1:] + j, 2 * rows[:-1] + i] = off[:, :, i, j]
        jac = h[..., None] * t                                         # d(constraint)/d(step) per piece: 3 x 2
        for axis in range(2):
            k[:, 2 * rows + axis, 2 * n:] = jac[:, :, :, axis]
            k[:, 2 * n:, 2 * rows + axis] = jac[:, :, :, axis].transpose(0, 2, 1)
        rhs = -np.concatenate([g.reshape(poses, -1) - np.einsum("pfkc,pk->pfc", jac, lam).reshape(poses, -1), c],
                              axis=1)
        sol = np.linalg.solve(k, rhs[..., None])[..., 0]
        step = sol[:, :2 * n].reshape(poses, n, 2)
        turn = np.linalg.norm(step, axis=2).max(axis=1)
        scale = np.minimum(1.0, MAX_TURN / np.maximum(turn, 1e-300))
        lam = lam + scale[:, None] * (sol[:, 2 * n:] - lam)
        moved = d + np.einsum("pfkc,pfc->pfk", t, step * scale[:, None, None])
        d = moved / np.linalg.norm(moved, axis=2, keepdims=True)
        if turn.max() < 1e-10 and np.abs(c).max() < TOLERANCE:
            break
    return d, np.linalg.norm(h[:, 0] * d.sum(axis=1) - targets, axis=1)


def _directions(frames: list[Frame]) -> np.ndarray:
    """The clamps' unit directions (poses x 3)."""
    return np.array([f.dir / np.linalg.norm(f.dir) for f in frames])


def _energy(starts: np.ndarray, ends: np.ndarray, d: np.ndarray) -> np.ndarray:
    """Each pose's bending energy, up to the factor 1/h its poses share (starts, ends: the clamps' unit directions)."""
    first, last = starts[:, None, :], ends[:, None, :]
    return (np.sum(np.diff(d, axis=1) ** 2, axis=(1, 2)) + 2 * np.sum((d[:, :1] - first) ** 2, axis=(1, 2))
            + 2 * np.sum((last - d[:, -1:]) ** 2, axis=(1, 2)))


def _rotate(v: np.ndarray, frm: np.ndarray, to: np.ndarray) -> np.ndarray:
    """v (... x 3) turned by the smallest rotation that takes unit vector frm to unit vector to (both ... x 3)."""
    axis = np.cross(frm, to)
    s = np.linalg.norm(axis, axis=-1, keepdims=True)
    c = np.sum(frm * to, axis=-1, keepdims=True)
    axis = np.where(s > 1e-12, axis / np.maximum(s, 1e-300), 0.0)
    return v * c + np.cross(axis, v) * s + axis * np.sum(axis * v, axis=-1, keepdims=True) * (1 - c)


def _carried(up: np.ndarray, start: np.ndarray, d: np.ndarray) -> np.ndarray:
    """Clamp A's face normal (poses x 3) carried along each pose's pieces without turning about the cable: from the
    clamp's direction to the first piece and on, piece by piece (poses x pieces x 3)."""
    normal = up - np.sum(up * start, axis=1, keepdims=True) * start
    previous = start
    out = np.empty_like(d)
    for i in range(d.shape[1]):
        piece = d[:, i]
        normal = _rotate(normal / np.linalg.norm(normal, axis=1, keepdims=True), previous, piece)
        normal -= np.sum(normal * piece, axis=1, keepdims=True) * piece
        out[:, i] = normal / np.linalg.norm(normal, axis=1, keepdims=True)
        previous = piece
    return out


@dataclass(frozen=True)
class Curve:
    """The span's modelled cable: its nodes (SEGMENTS + 1, from clamp A to clamp B) and per piece between them its
    direction, the carried face normal and the width direction (across a flat cable's width); the clamps'
    directions, which the first and last pieces turn from and to over half a piece."""
    points: np.ndarray
    directions: np.ndarray
    normals: np.ndarray
    widths: np.ndarray
    piece: float             # each piece's length (mm)
    start: np.ndarray        # clamp A's direction (unit)
    end: np.ndarray          # clamp B's direction (unit)


def curves(a: list[Frame], b: list[Frame], length: float, segments: int = SEGMENTS) -> list[Curve]:
    """The elastica `length` long from a[i] to b[i] in `segments` pieces, for each i (the span at each pose)."""
    targets = np.array([q.at - p.at for p, q in zip(a, b)])
    chords = np.linalg.norm(targets, axis=1)
    far = int(np.argmax(chords - length))
    if length < chords[far] - 1e-9:
        raise SpanError(f"a {length:.1f} mm span cannot reach between clamps {chords[far]:.1f} mm apart", far)
    # Two ways to the shape, and per pose the converged one of least energy: relaxed from the Hermite curve of the
    # full length, and paid out from nearly taut (relaxed at the chord plus a tenth of the slack from the Hermite
    # curve, which has no loops that short, then lengthened in steps, each relaxed from the last), the shape a cable
    # fed between the clamps takes. Either alone can end in a curled, higher-energy equilibrium, or not converge.
    starts, ends = _directions(a), _directions(b)
    guesses = np.array([_first_guess(p, q, length, segments) for p, q in zip(a, b)])
    direct, direct_gap = _relax(starts, ends, targets, np.full(len(a), float(length)), guesses)
    paid = None
    for share in PAY_OUT:
        lengths = chords + share * (length - chords)
        if paid is None:
            paid = np.array([_first_guess(p, q, float(l), segments) for p, q, l in zip(a, b, lengths)])
        paid, paid_gap = _relax(starts, ends, targets, lengths, paid)
    ok_direct, ok_paid = direct_gap <= 10 * TOLERANCE, paid_gap <= 10 * TOLERANCE
    take_paid = ok_paid & (~ok_direct | (_energy(starts, ends, paid) < _energy(starts, ends, direct)))
    d_all = np.where(take_paid[:, None, None], paid, direct)
    gap = np.where(take_paid, paid_gap, direct_gap)
    worst = int(np.argmax(gap))
    if gap[worst] > 10 * TOLERANCE:
        raise SpanError(f"no curve {length:.1f} mm long reaches between the clamps along their directions (it ends "
                        f"{gap[worst]:.3f} mm short)", worst)
    h = length / segments
    normals = _carried(np.array([p.up for p in a]), starts, d_all)
    return [Curve(p.at + np.vstack([np.zeros(3), np.cumsum(h * d, axis=0)]), d, n, np.cross(d, n), h, s, e)
            for p, d, n, s, e in zip(a, d_all, normals, starts, ends)]


def curve(a: Frame, b: Frame, length: float, segments: int = SEGMENTS) -> Curve:
    """The elastica `length` long from A to B in `segments` pieces."""
    return curves([a], [b], length, segments)[0]


def arc_lengths(c: Curve) -> np.ndarray:
    """Distance along the curve from A to each node (mm)."""
    return np.arange(len(c.points)) * c.piece


def measure(c: Curve, b: Frame) -> Shape:
    """Bend radius, in-plane bend radius and twist of a span's curve ending at clamp B."""
    d = c.directions
    # Every turn: from clamp A's direction to the first piece, between neighbouring pieces, from the last piece to
    # B's; the end turns are taken over half a piece. A turn of angle t between pieces of length h lies on a circle
    # of radius h / (2 sin(t/2)) through the nodes; an end turn of angle t over half a piece, on one of h / (2 sin t).
    frm = np.vstack([c.start, d])
    to = np.vstack([d, c.end])
    angle = np.arccos(np.clip(np.sum(frm * to, axis=1), -1.0, 1.0))
    over = np.full(len(angle), 1.0)
    over[0] = over[-1] = 0.5
    sine = np.sin(np.where(over < 1, angle, angle / 2))
    radius = c.piece / np.maximum(2 * sine, 1e-12)
    # The turn's component along the face's width direction (at a node, the two pieces' mean) is in-plane bending.
    width = np.vstack([c.widths[:1], c.widths[:-1] + c.widths[1:], c.widths[-1:]])
    width /= np.maximum(np.linalg.norm(width, axis=1), 1e-12)[:, None]
    inplane = np.abs(np.sum((to - frm) * width, axis=1)) / (over * c.piece)
    end_normal = _rotate(c.normals[-1], d[-1], c.end)
    end_up = b.up - np.dot(b.up, c.end) * c.end
    end_up /= np.linalg.norm(end_up)
    twist = math.degrees(math.atan2(float(np.dot(np.cross(end_normal, end_up), c.end)),
                                    float(np.dot(end_normal, end_up))))
    return Shape(c.piece * len(d), float(radius.min()), float(1 / max(inplane.max(), 1e-12)), twist)


def shape(a: Frame, b: Frame, length: float) -> Shape:
    return measure(curve(a, b, length), b)
