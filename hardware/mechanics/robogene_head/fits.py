# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""ISO 286 fits of the bearing seats, found in the assembly, and what the drawings print about them.

A machined part's cylindrical face that shares its axis and diameter with a bearing's outer ring is a housing
seat; one that shares them with a bearing's bore is a journal. Which fit each gets (the parameter file's fits:
section) depends on which ring turns against the load. The load (the head's weight) stands still relative to
the part nearer the neck base, so on a bearing whose housing is on that part the inner ring turns: a tight
journal and a sliding housing seat. Where the housing is on the part further out (the yaw bearing in the head
floor, on its fixed yaw shaft) the outer ring turns: a tight housing seat and a sliding journal. Two seats of one
bearing pair on one part must also be coaxial (fits.coaxiality); the drawing names them as datums A and B.

The limit deviations come from ISO 286-1 / 286-2 (the IT grades and the fundamental deviations of the letters
used here, for nominal sizes up to 30 mm)."""
from __future__ import annotations

import math
from dataclasses import dataclass

from OCP.BRepAdaptor import BRepAdaptor_Surface
from OCP.GeomAbs import GeomAbs_Cylinder

from robogene_head_model.params import HeadParameters, ParameterError

from . import kinematics
from .geom import location

TOL = 1e-3    # mm: a seat and a ring share axis and diameter to this

# ISO 286-1 standard tolerance grades (um) by nominal size range (over, up to] in mm.
RANGES = ((0, 3), (3, 6), (6, 10), (10, 18), (18, 30))
IT = {6: (6, 8, 9, 11, 13), 7: (10, 12, 15, 18, 21)}
# Fundamental deviations (um) by range: shafts give es (upper) or ei (lower), holes EI or ES.
SHAFT_ES = {"h": (0, 0, 0, 0, 0), "g": (-2, -4, -5, -6, -7)}
SHAFT_EI = {"k": (0, 1, 1, 1, 2), "js": None}
HOLE_EI = {"H": (0, 0, 0, 0, 0), "G": (2, 4, 5, 6, 7)}
# M7 up to 30 mm: ES = -m + delta = 0 (ISO 286-2 table of M)
HOLE_ES = {"M": (-2, 0, 0, 0, 0)}


def deviations(diameter: float, tolerance: str) -> tuple[float, float]:
    """(upper, lower) limit deviations in mm of e.g. "H7" or "k6" at a nominal diameter."""
    letters, grade = tolerance.rstrip("0123456789"), tolerance[len(tolerance.rstrip("0123456789")):]
    if not grade or int(grade) not in IT:
        raise ValueError(f"tolerance {tolerance!r}: grade must be one of IT{', IT'.join(map(str, IT))}")
    i = next((k for k, (lo, hi) in enumerate(RANGES) if lo < diameter <= hi), None)
    if i is None:
        raise ValueError(f"tolerance {tolerance!r}: nominal size {diameter:g} mm is beyond the table (up to 30 mm)")
    it = IT[int(grade)][i]
    if letters in SHAFT_ES:
        es = SHAFT_ES[letters][i]
        return es / 1000, (es - it) / 1000
    if letters == "js":
        return it / 2000, -it / 2000
    if letters in SHAFT_EI:
        ei = SHAFT_EI[letters][i]
        return (ei + it) / 1000, ei / 1000
    if letters in HOLE_EI:
        ei = HOLE_EI[letters][i]
        return (ei + it) / 1000, ei / 1000
    if letters in HOLE_ES:
        es = HOLE_ES[letters][i]
        return es / 1000, (es - it) / 1000
    raise ValueError(f"tolerance {tolerance!r}: letter {letters!r} is not in the table "
                     f"(holes {sorted(HOLE_EI) + sorted(HOLE_ES)}, shafts {sorted(SHAFT_ES) + sorted(SHAFT_EI)})")


@dataclass(frozen=True)
class Fit:
    design: str
    role: str            # "housing" or "journal"
    bearing: str         # catalogue key
    diameter: float
    tolerance: str       # ISO 286, e.g. "H7"
    upper: float         # mm
    lower: float
    count: int           # seats of this kind on the part (per instance)
    coaxial: float       # mm, cylindrical zone for the pair on one part (0: a single seat)

    def text(self) -> str:
        def dev(v):   # in mm to the micrometre, half micrometres where js gives them
            text = f"{v:+.4f}"
            return "0" if abs(v) < 5e-7 else (text[:-1] if text.endswith("0") else text)
        what = "bearing seat" if self.role == "housing" else "bearing journal"
        count = f"{self.count}x " if self.count > 1 else ""
        head = f"{count}⌀{self.diameter:g} {self.tolerance} ({dev(self.upper)}/{dev(self.lower)}) {what}s" \
            if self.count > 1 else f"⌀{self.diameter:g} {self.tolerance} ({dev(self.upper)}/{dev(self.lower)}) {what}"
        if self.coaxial:
            head += f", coaxial within {self.coaxial:g} (cylindrical zone) to their common axis A-B"
        return head


def _fits(params: HeadParameters):
    return params.root.node("fits")


def tolerance(params: HeadParameters, role: str, turns: bool) -> str:
    """The fit of a housing or journal whose ring turns (True) or stands (False) against the load."""
    key = f"{role}_{'turning' if turns else 'standing'}_ring"
    value = _fits(params).text(key)
    try:
        deviations(10, value)
    except ValueError as exc:
        raise ParameterError(f"{params.path}: fits.{key}: {exc}") from None
    return value


def _cylinders(shape) -> list:
    """(diameter, point on the axis, direction, v0, v1) per cylindrical face: it spans point + v direction."""
    out = []
    for face in shape.Faces():
        surf = BRepAdaptor_Surface(face.wrapped)
        if surf.GetType() != GeomAbs_Cylinder:
            continue
        axis = surf.Cylinder().Axis()
        o, a = axis.Location(), axis.Direction()
        out.append((2 * surf.Cylinder().Radius(), (o.X(), o.Y(), o.Z()), (a.X(), a.Y(), a.Z()),
                    surf.FirstVParameter(), surf.LastVParameter()))
    return out


def _span(cylinder, origin, unit) -> tuple[float, float]:
    """Where a cylindrical face lies along the unit vector, measured from origin."""
    _, p, d, v0, v1 = cylinder
    base = sum((a - b) * u for a, b, u in zip(p, origin, unit))
    sign = sum(a * u for a, u in zip(d, unit))
    return tuple(sorted((base + v0 * sign, base + v1 * sign)))


def _same_line(p, d, q, e) -> bool:
    cross = (d[1] * e[2] - d[2] * e[1], d[2] * e[0] - d[0] * e[2], d[0] * e[1] - d[1] * e[0])
    if math.sqrt(sum(c * c for c in cross)) > TOL:
        return False
    w = tuple(b - a for a, b in zip(p, q))
    along = sum(x * y for x, y in zip(w, d))
    return math.dist(w, tuple(along * c for c in d)) <= TOL


def _depth(params: HeadParameters, link: str) -> int:
    """How many joints lie between the link and the neck base."""
    depth, parents = 0, {j.child: j.parent for j in params.joints.values()}
    while link != kinematics.ROOT_LINK:
        link, depth = parents[link], depth + 1
    return depth


def find(params: HeadParameters, parts: list) -> dict[str, list[Fit]]:
    """design -> its fits, from the assembly at rest."""
    poses = kinematics.link_poses(params, {})
    world = {p.name: p.shape.moved(location(poses[p.link])) for p in parts if p.kind in ("machined", "purchased")}
    catalog = params.root.node("purchased")
    bearings = [p for p in parts if p.kind == "purchased" and catalog.has(p.design)
                and params.purchased(p.design).text("kind") == "bearing"]
    coaxial = _fits(params).num("coaxiality", positive=True)
    found: dict[str, dict[tuple, dict]] = {}
    for b in bearings:
        item = params.purchased(b.design)
        rings = {"housing": item.num("outside"), "journal": item.num("bore")}
        outer = next((c for c in _cylinders(world[b.name]) if abs(c[0] - rings["housing"]) < TOL), None)
        if outer is None:
            continue
        origin, unit = outer[1], outer[2]
        lo, hi = _span(outer, origin, unit)
        seats = {}
        for part in parts:
            if part.kind != "machined":
                continue
            for role, dia in rings.items():
                for c in _cylinders(world[part.name]):
                    if abs(c[0] - dia) < TOL and _same_line(origin, unit, c[1], c[2]):
                        c_lo, c_hi = _span(c, origin, unit)
                        if min(hi, c_hi) - max(lo, c_lo) > TOL:     # the seat holds the ring along its width
                            seats[role] = part
        if "housing" not in seats or "journal" not in seats:
            continue
        # the ring on the part nearer the base stands still relative to the load
        # (or the journal is a shaft that turns in its own link's housing, against a load standing in it)
        inner_turns = (_depth(params, seats["housing"].link) < _depth(params, seats["journal"].link)
                       or seats["journal"].turning)
        for role, part in seats.items():
            turns = inner_turns if role == "journal" else not inner_turns
            tol = tolerance(params, role, turns)
            entry = found.setdefault(part.design, {}).setdefault((role, b.design, tol), {"parts": {}, "n": 0})
            entry["parts"][part.name] = entry["parts"].get(part.name, 0) + 1
    out = {}
    for design, entries in found.items():
        fits = []
        for (role, key, tol), entry in sorted(entries.items()):
            per_instance = max(entry["parts"].values())
            dia = params.purchased(key).num("outside" if role == "housing" else "bore")
            upper, lower = deviations(dia, tol)
            fits.append(Fit(design, role, key, dia, tol, upper, lower, per_instance,
                            coaxial if per_instance == 2 else 0.0))
        out[design] = fits
    return out


def note(fits: list[Fit]) -> str:
    """The drawing's line about the part's fits (ISO 286)."""
    return "FITS ISO 286: " + "; ".join(f.text() for f in fits) + "."
