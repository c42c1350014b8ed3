# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The round holes of a part, read from its solid: diameter, whether it goes through, its depth from the face it
opens on, a counterbore at its mouth, and the thread of a tapped one (from the build: a STEP cannot say).

A hole is a run of coaxial cylindrical faces, whole circles with the material outside, that follow each other
along an axis parallel to X, Y or Z (the views look along these). Each end of the run either opens (just past it
on the axis there is no material) or is a flat bottom. The smallest diameter is the hole's; a wider face at an
open end is a counterbore (or a seat) of its depth. Depths are measured from the open end; a blind hole with a
counterbore is measured from the face the counterbore opens on.

classify() is pure Python; cylinder_segments() reads a FreeCAD Part shape."""
from __future__ import annotations

import math
from dataclasses import dataclass, field

TOL = 1e-4         # mm: two faces meet, or share an axis
PROBE = 0.01       # mm past a run's end where material is looked for


@dataclass(frozen=True)
class Segment:
    axis: int            # 0, 1, 2: the model axis the hole runs along
    u: float             # the axis line's coordinates on the other two model axes, in order
    v: float
    d: float             # diameter
    lo: float            # extent along the axis
    hi: float


@dataclass
class Hole:
    axis: int
    u: float
    v: float
    segments: list       # Segment, by lo
    open_lo: bool        # no material just below lo on the axis
    open_hi: bool
    thread: str = ""     # "M3" when the build says the main bore is tapped
    counterbores: list = field(default_factory=list)   # (segment, +1 | -1: the end it opens at)

    @property
    def main(self) -> Segment:
        return min(self.segments, key=lambda s: s.d)

    @property
    def through(self) -> bool:
        return self.open_lo and self.open_hi

    @property
    def depth(self) -> float | None:
        """From the open end to the bottom; None for a through hole."""
        if self.through:
            return None
        return self.segments[-1].hi - self.segments[0].lo

    @property
    def opens(self) -> list:
        """The directions along the axis the hole opens towards: -1 (at lo), +1 (at hi)."""
        return [s for s, o in ((-1, self.open_lo), (1, self.open_hi)) if o]


def point(axis: int, u: float, v: float, t: float) -> tuple:
    """The model point at t along the axis on the line (u, v)."""
    p = [u, v]
    p.insert(axis, t)
    return tuple(p)


def classify(segments: list, inside) -> list:
    """Holes from cylinder segments; inside(x, y, z) -> True where the part has material."""
    lines: dict = {}
    for s in segments:
        key = (s.axis, round(s.u / TOL), round(s.v / TOL))
        if all(abs(o.lo - s.lo) > TOL or abs(o.hi - s.hi) > TOL or abs(o.d - s.d) > TOL for o in lines.get(key, [])):
            lines.setdefault(key, []).append(s)
    holes = []
    for group in lines.values():
        group.sort(key=lambda s: s.lo)
        runs = [[group[0]]]
        for s in group[1:]:
            if abs(s.lo - runs[-1][-1].hi) <= TOL:
                runs[-1].append(s)
            else:
                runs.append([s])
        for run in runs:
            first = run[0]
            hole = Hole(first.axis, first.u, first.v, run,
                        not inside(*point(first.axis, first.u, first.v, run[0].lo - PROBE)),
                        not inside(*point(first.axis, first.u, first.v, run[-1].hi + PROBE)))
            if not (hole.open_lo or hole.open_hi):
                continue            # a closed cavity: no tool reaches it along this axis
            main = hole.main
            if hole.open_lo and run[0].d > main.d + TOL:
                hole.counterbores.append((run[0], -1))
            if hole.open_hi and len(run) > 1 and run[-1].d > main.d + TOL:
                hole.counterbores.append((run[-1], 1))
            holes.append(hole)
    return holes


def apply_threads(holes: list, threads: list) -> None:
    """Mark the holes whose main bore is one of the build's tapped holes (threads.TappedHole.as_dict)."""
    for t in threads:
        direction = t["direction"]
        axis = max(range(3), key=lambda i: abs(direction[i]))
        if abs(abs(direction[axis]) - 1) > 1e-6:
            continue                 # not along X, Y or Z: not called out
        others = [i for i in range(3) if i != axis]
        lo, hi = t["span"]
        for h in holes:
            m = h.main
            if (h.axis == axis and abs(h.u - t["point"][others[0]]) < 1e-3 and abs(h.v - t["point"][others[1]]) < 1e-3
                    and abs(m.d - t["diameter"]) < 1e-3 and min(hi, m.hi) - max(lo, m.lo) > 1e-3):
                h.thread = t["thread"]


def cylinder_segments(shape) -> list:
    """The whole-circle cylindrical faces of a FreeCAD shape with the material outside, axis along X, Y or Z."""
    import Part
    out = []
    for face in shape.Faces:
        surf = face.Surface
        if not isinstance(surf, Part.Cylinder):
            continue
        u0, u1, v0, v1 = face.ParameterRange
        if abs(u1 - u0) < 2 * math.pi - 1e-6:
            continue                 # a part of a circle: a slot end, a fillet, an arc of the outline
        a = surf.Axis
        axis = max(range(3), key=lambda i: abs(a[i]))
        if abs(abs(a[axis]) - 1) > 1e-9:
            continue
        c = surf.Center
        u_mid, v_mid = (u0 + u1) / 2, (v0 + v1) / 2
        on = face.valueAt(u_mid, v_mid)
        radial = on - c - a * ((on - c).dot(a))
        if radial.dot(face.normalAt(u_mid, v_mid)) > 0:
            continue                 # material inside: a shaft or a boss
        ends = sorted(((c + a * v0)[axis], (c + a * v1)[axis]))
        others = [c[i] for i in range(3) if i != axis]
        out.append(Segment(axis, others[0], others[1], 2 * surf.Radius, ends[0], ends[1]))
    return out
