# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""ISO 286 fits of the bearing seats, found in the assembly, and of the clamp bores, and what the drawings print about them.

A machined part's cylindrical face that shares its axis and diameter with a bearing's outer ring is a housing
seat; one that shares them with a bearing's bore is a journal. Which fit each gets (the parameter file's fits:
section) depends on which ring turns against the load. The load (the head's weight) stands still relative to
the part nearer the neck base, so on a bearing whose housing is on that part the inner ring turns: a tight
journal and a sliding housing seat. Where the housing is on the part further out (the yaw bearing in the head
floor, on its fixed yaw shaft) the outer ring turns: a tight housing seat and a sliding journal. Two seats of one
bearing pair on one part must also be coaxial (fits.coaxiality); the drawing names them as datums A and B. A machined
part's bores that clamp a shaft (Part.clamp_bores: the made couplings') get fits.clamp_bore.

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
# ISO 492 normal tolerance class of radial bearings: the lower deviation (um) of the mean bore (by bore, over..up to
# mm) and of the mean outside diameter (by outside diameter); the upper deviations are 0.
RING_BORE = (((2.5, 10), -8), ((10, 18), -8), ((18, 30), -10))
RING_OUTSIDE = (((6, 18), -8), ((18, 30), -9), ((30, 50), -11))


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
    role: str            # "housing", "journal" or "clamp" (a bore that clamps a shaft)
    bearing: str         # catalogue key ("" for a clamp bore)
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
        what = {"housing": "bearing seat", "journal": "bearing journal", "clamp": "clamp bore"}[self.role]
        count = f"{self.count}x " if self.count > 1 else ""
        head = f"{count}⌀{self.diameter:g} {self.tolerance} ({dev(self.upper)}/{dev(self.lower)}) {what}s" \
            if self.count > 1 else f"⌀{self.diameter:g} {self.tolerance} ({dev(self.upper)}/{dev(self.lower)}) {what}"
        if self.coaxial:
            head += f", coaxial within {self.coaxial:g} (cylindrical zone) to their common axis A-B"
        return head


def _fits(params: HeadParameters):
    return params.root.node("fits")


def _checked(params: HeadParameters, key: str) -> str:
    """fits.<key>, an ISO 286 tolerance the table here knows."""
    value = _fits(params).text(key)
    try:
        deviations(10, value)
    except ValueError as exc:
        raise ParameterError(f"{params.path}: fits.{key}: {exc}") from None
    return value


def tolerance(params: HeadParameters, role: str, turns: bool) -> str:
    """The fit of a housing or journal whose ring turns (True) or stands (False) against the load."""
    return _checked(params, f"{role}_{'turning' if turns else 'standing'}_ring")


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


@dataclass(frozen=True)
class Seat:
    """Where one bearing sits: the machined parts holding its outer ring (housing) and its bore (journal), the ISO 286
    fit of each and which ring turns against the load (that one is the tight ring)."""
    bearing: str          # part name
    key: str              # catalogue key
    housing: str          # part names
    journal: str
    housing_tolerance: str
    journal_tolerance: str
    inner_turns: bool

    @property
    def tight_ring(self) -> str:
        return "inner" if self.inner_turns else "outer"

    @property
    def sliding_ring(self) -> str:
        return "outer" if self.inner_turns else "inner"

    def tolerance(self, ring: str) -> str:
        return self.journal_tolerance if ring == "inner" else self.housing_tolerance


def seats(params: HeadParameters, parts: list) -> dict[str, Seat]:
    """bearing part name -> its seat, from the assembly at rest; bearings without both a housing and a journal are
    left out."""
    poses = kinematics.link_poses(params, {})
    world = {p.name: p.shape.moved(location(poses[p.link])) for p in parts if p.kind in ("machined", "purchased")}
    catalog = params.root.node("purchased")
    bearings = [p for p in parts if p.kind == "purchased" and catalog.has(p.design)
                and params.purchased(p.design).text("kind") == "bearing"]
    machined = [(part, _cylinders(world[part.name])) for part in parts if part.kind == "machined"]
    out = {}
    for b in bearings:
        item = params.purchased(b.design)
        rings = {"housing": item.num("outside"), "journal": item.num("bore")}
        outer = next((c for c in _cylinders(world[b.name]) if abs(c[0] - rings["housing"]) < TOL), None)
        if outer is None:
            continue
        origin, unit = outer[1], outer[2]
        lo, hi = _span(outer, origin, unit)
        found = {}
        for part, cylinders in machined:
            for role, dia in rings.items():
                for c in cylinders:
                    if abs(c[0] - dia) < TOL and _same_line(origin, unit, c[1], c[2]):
                        c_lo, c_hi = _span(c, origin, unit)
                        if min(hi, c_hi) - max(lo, c_lo) > TOL:     # the seat holds the ring along its width
                            found[role] = part
        if "housing" not in found or "journal" not in found:
            continue
        # the ring on the part nearer the base stands still relative to the load
        # (or the journal is a shaft that turns in its own link's housing, against a load standing in it)
        inner_turns = (_depth(params, found["housing"].link) < _depth(params, found["journal"].link)
                       or found["journal"].turning)
        out[b.name] = Seat(b.name, b.design, found["housing"].name, found["journal"].name,
                           tolerance(params, "housing", not inner_turns), tolerance(params, "journal", inner_turns),
                           inner_turns)
    return out


def find(params: HeadParameters, parts: list) -> dict[str, list[Fit]]:
    """design -> its fits, from the assembly at rest."""
    by_name = {p.name: p for p in parts}
    coaxial = _fits(params).num("coaxiality", positive=True)
    found: dict[str, dict[tuple, dict]] = {}
    for seat in seats(params, parts).values():
        for role, name, tol in (("housing", seat.housing, seat.housing_tolerance),
                                ("journal", seat.journal, seat.journal_tolerance)):
            part = by_name[name]
            entry = found.setdefault(part.design, {}).setdefault((role, seat.key, tol), {"parts": {}, "n": 0})
            entry["parts"][part.name] = entry["parts"].get(part.name, 0) + 1
    out, done = {}, set()
    for design, entries in found.items():
        fits = []
        for (role, key, tol), entry in sorted(entries.items()):
            per_instance = max(entry["parts"].values())
            dia = params.purchased(key).num("outside" if role == "housing" else "bore")
            upper, lower = deviations(dia, tol)
            fits.append(Fit(design, role, key, dia, tol, upper, lower, per_instance,
                            coaxial if per_instance == 2 else 0.0))
        out[design] = fits
    clamp = None
    for part in parts:
        if part.kind != "machined" or not part.clamp_bores or part.design in done:
            continue
        done.add(part.design)
        clamp = clamp or _checked(params, "clamp_bore")
        out.setdefault(part.design, []).extend(
            Fit(part.design, "clamp", "", d, clamp, *deviations(d, clamp), 1, 0.0) for d in part.clamp_bores)
    return out


def ring_deviations(diameter: float, ring: str) -> tuple[float, float]:
    """(upper, lower) deviations in mm of a radial ball bearing's mean bore (ring "inner") or outside diameter
    ("outer"), ISO 492 normal tolerance class."""
    table = RING_BORE if ring == "inner" else RING_OUTSIDE
    for (lo, hi), low in table:
        if lo < diameter <= hi:
            return 0.0, low / 1000
    raise ValueError(f"a bearing {'bore' if ring == 'inner' else 'outside diameter'} of {diameter:g} mm is beyond the "
                     f"ISO 492 table here")


def clearance(seat: Seat, params: HeadParameters, ring: str) -> tuple[float, float, float]:
    """(least, mean, most) clearance in mm between a bearing's ring and its seat; negative: interference."""
    item = params.purchased(seat.key)
    dia = item.num("bore" if ring == "inner" else "outside")
    s_up, s_lo = deviations(dia, seat.tolerance(ring))
    r_up, r_lo = ring_deviations(dia, ring)
    if ring == "inner":      # the shaft inside the ring
        least, most = r_lo - s_up, r_up - s_lo
    else:                    # the ring inside the bore
        least, most = s_lo - r_up, s_up - r_lo
    return least, (least + most) / 2, most


def slides(seat: Seat, params: HeadParameters, ring: str) -> bool:
    """A ring slides in its seat when the fit's mean is a clearance (SKF's loose fits: H7 housings, g6 and h6 shafts
    under a bearing of normal tolerance); a mean interference holds it."""
    return clearance(seat, params, ring)[1] > 0


def note(fits: list[Fit]) -> str:
    """The drawing's line about the part's fits (ISO 286)."""
    return "FITS ISO 286: " + "; ".join(f.text() for f in fits) + "."
