# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Each joint shaft's bearing arrangement, measured in the CAD: one fixed bearing, the others floating.

For every ball bearing that has a housing and a journal (fits.seats), each ring is probed along the bearing's axis,
both ways: a thin tube over the ring's face (the inner ring from its bore to its face's outer edge, the outer ring
from the pitch circle, or the catalogue's outer_ring_inside, to its outside) is intersected with the parts that stand
with that ring's seat (the housing's link for the outer ring, the journal's link for the inner ring; on a jackshaft,
whose shaft turns in a housing of its own link (jackshafts.find), the shaft and what turns with it for the inner ring,
the rest of the link for the outer ring); the nearest one is the ring's stop on that side and its distance the ring's
axial room. A shim is no stop: the probe goes on beyond
it. A ring is located on a side when its stop is within bearing_arrangement.located_within (the CAD is nominal).
  The bearing stops the shaft moving towards +axis when the shaft's side holds its inner ring on the -axis face and
  the housing holds its outer ring on the +axis face; likewise towards -axis. Both ways: a fixed bearing. One way:
  a bearing that locates one way (a cross-located pair is two of them, facing each other). Neither: floating.
A floating bearing must let its sliding ring move (the ring whose fit's mean is a clearance, fits.slides) at least
  g(L) + t(L)
each way, where L is its distance from the fixed bearing along the axis, g(L) the shaft's growth against its housing
over L in the worst of thermal_growth's cases, from the shaft's (the journal's) and the housing's own materials, and
t(L) the ISO 2768-m tolerance of a length L (the drawings' general tolerance, which places the seats), and its tight
ring must sit against a shoulder.
A retaining ring that bears straight on a ring (no shim between) must stay within that ring's face (ring_faces), and
so must a shim that bears on a ring (shim_faces): a shim beside a sealed or shielded bearing locates the ring it
touches, never the seal or shield between the rings.
Per joint: the joints under gearhead_fixed have the gearhead's own (preloaded) output bearings as their fixed
bearing, which counts when the gearhead's axis is the shaft's: every ball bearing there must float. The joints under
cross_located have two bearings each locating one way, in opposite directions. Every other joint, and every
jackshaft, has exactly one fixed bearing and the rest floating. Anything else fails the build, naming the joint and the bearing."""
from __future__ import annotations

import json
from dataclasses import asdict, dataclass, field

import numpy as np

from robogene_head_model.params import CHAIN_JOINTS, HeadParameters, ParameterError

from . import fits, geom, jackshafts, kinematics, thermal_growth
from .geom import exact_bounds, location

EDGE = 0.05        # mm the probe keeps inside a ring's face, off the seat's own cylinder
ON_AXIS = 1e-3     # mm: a gearhead's axis this close to the shaft's is on it
# ISO 2768-1 class m: permissible deviations (mm) of linear sizes by nominal length (over, up to] mm.
ISO_2768_M = (((0.5, 6), 0.1), ((6, 30), 0.2), ((30, 120), 0.3), ((120, 400), 0.5), ((400, 1000), 0.8))


class BearingArrangementError(RuntimeError):
    """A shaft without one fixed bearing, or a floating bearing that cannot move; the message names them."""


@dataclass(frozen=True)
class Side:
    gap: float | None     # mm from the ring's face to its stop; None: no stop within the search length
    stop: str             # the stop's part name ("" when none)
    through: tuple = ()   # the shims between the ring and its stop, the ring's neighbour first
    shim_gap: float | None = None   # mm from the ring's face to the first of them


@dataclass(frozen=True)
class Ring:
    ring: str             # "inner" or "outer"
    seat: str             # the machined part it sits in or on
    tolerance: str        # ISO 286
    slides: bool
    mean_clearance: float  # mm, negative: interference
    minus: Side           # towards -axis (the bearing's axis, see BearingState.axis)
    plus: Side


@dataclass(frozen=True)
class ShimFace:
    """A shim that bears on a bearing's ring, and the part of that ring's face it may cover."""
    shim: str             # part name
    design: str           # catalogue key
    ring: str             # "inner" or "outer"
    bore: float           # mm, the shim's
    outside: float
    face: tuple           # (inside, outside) mm: the ring's face, between its bore or outside and its seal or shield
    ok: bool


@dataclass
class BearingState:
    joint: str
    bearing: str
    key: str
    axis: list            # world unit vector of the bearing's +axis
    centre: list          # world mm
    role: str             # "fixed", "one way", "floating"
    stops_shaft: list     # "+axis" / "-axis": the shaft's motions relative to the housing this bearing stops
    inner: Ring
    outer: Ring
    span: float | None = None          # mm along the axis from the joint's fixed bearing (floating bearings)
    required: float | None = None      # mm of room each way the sliding ring needs
    growth: str = ""                   # the materials and the thermal case that governs `required`
    shims: list = field(default_factory=list)   # ShimFace: the shims that bear on its rings (shim_faces)

    def ring(self, name: str) -> Ring:
        return self.inner if name == "inner" else self.outer


@dataclass
class JointResult:
    joint: str
    arrangement: str      # "gearhead + floating", "fixed + floating", "cross-located"
    fixed: str            # the fixed bearing (a part name, or the gearhead's)
    bearings: list[BearingState]
    problems: list[str] = field(default_factory=list)


@dataclass
class Report:
    located_within: float
    search: float
    joints: list[JointResult]
    problems: list[str]

    @property
    def ok(self) -> bool:
        return not self.problems and not any(j.problems for j in self.joints)

    @property
    def failures(self) -> list[str]:
        return self.problems + [p for j in self.joints for p in j.problems]


def _node(params: HeadParameters):
    return params.root.node("bearing_arrangement")


def _joint_list(params: HeadParameters, key: str) -> list[str]:
    value = _node(params).raw(key)
    if not isinstance(value, list) or not all(j in CHAIN_JOINTS for j in value):
        raise ParameterError(f"{params.path}: bearing_arrangement.{key}: expected a list of chain joints "
                             f"({', '.join(CHAIN_JOINTS)}), got {value!r}")
    return value


def general_tolerance(length: float) -> float:
    """ISO 2768-m permissible deviation (mm) of a length (mm)."""
    for (lo, hi), t in ISO_2768_M:
        if lo < length <= hi:
            return t
    raise ValueError(f"a length of {length:g} mm is outside ISO 2768-m's table (0.5 to 1000 mm)")


def required_float(params: HeadParameters, span: float, shaft: tuple[str, str], housing: tuple[str, str]) \
        -> tuple[float, thermal_growth.Growth, float]:
    """(room each way, thermal growth, tolerance) in mm for a floating bearing `span` mm from the fixed one, its shaft
    and housing given as (part name, material)."""
    growth = thermal_growth.differential(params, shaft, housing, span)
    tol = general_tolerance(span)
    return growth.mm + tol, growth, tol


def _annulus(params: HeadParameters, key: str, ring: str) -> tuple[float, float]:
    """Radii (mm) of a ring's face: what a stop must overlap to hold that ring."""
    item = params.purchased(key)
    d, big = item.num("bore", positive=True), item.num("outside", positive=True)
    if ring == "inner":
        return d / 2 + EDGE, item.num("inner_ring_outside", positive=True) / 2 - EDGE
    inside = item.num("outer_ring_inside") if item.has("outer_ring_inside") else (d + big) / 2
    return inside / 2 + EDGE, big / 2 - EDGE


class _Probe:
    """Parts in one bearing's frame (its axis +z, its faces at z = 0 and z = width), probed along z."""

    def __init__(self, params: HeadParameters, poses: dict, frame: np.ndarray, width: float, search: float):
        self.params, self.poses, self.width, self.search = params, poses, width, search
        self.inverse = np.linalg.inv(frame)
        self.local: dict[str, object] = {}
        self.catalog = params.root.node("purchased")

    def _shape(self, part):
        if part.name not in self.local:
            self.local[part.name] = part.shape.moved(location(self.inverse @ self.poses[part.link]))
        return self.local[part.name]

    def _is_shim(self, part) -> bool:
        return part.kind == "purchased" and self.catalog.has(part.design) \
            and self.params.purchased(part.design).text("kind") == "shim"

    def side(self, candidates: list, radii: tuple[float, float], sign: int, skip: set[str]) -> Side:
        """The nearest stop of a ring among `candidates` beyond the ring's face towards sign * z, through shims."""
        face = self.width if sign > 0 else 0.0
        end = face + sign * self.search
        free, skip, shims, first = 0.0, set(skip), [], None
        while (end - face) * sign > 1e-9:
            z0, z1 = sorted((face, end))
            probe = geom.tube("z", 2 * radii[1], 2 * radii[0], z0, z1)
            lo, hi = np.array([-radii[1], -radii[1], z0]), np.array([radii[1], radii[1], z1])
            best = None
            for part in candidates:
                if part.name in skip:
                    continue
                shape = self._shape(part)
                b0, b1 = exact_bounds(shape)
                if np.any(b0 > hi) or np.any(b1 < lo):
                    continue
                common = probe.intersect(shape)
                if common.Volume() < 1e-6:
                    continue
                c0, c1 = exact_bounds(common)
                near, far = (c0[2], c1[2]) if sign > 0 else (c1[2], c0[2])
                gap = abs(near - face)
                if best is None or gap < best[0]:
                    best = (gap, part, far)
            if best is None:
                return Side(None, "", tuple(shims), first)
            gap, part, far = best
            if not self._is_shim(part):
                return Side(round(free + gap, 4), part.name, tuple(shims), first)
            if first is None:
                first = round(gap, 4)
            free += gap           # a shim is pushed by whatever pushes it: its free room counts, its thickness not
            face = far
            skip.add(part.name)
            shims.append(part.name)
        return Side(None, "", tuple(shims), first)


def _joint_of(params: HeadParameters, a: str, b: str) -> str | None:
    for name in CHAIN_JOINTS:
        j = params.joints[name]
        if {j.parent, j.child} == {a, b}:
            return name
    return None


def _direction(v: np.ndarray) -> str:
    for i, name in enumerate("xyz"):
        if abs(abs(v[i]) - 1) < 1e-6:
            return ("+" if v[i] > 0 else "-") + name
    return "(" + ", ".join(f"{c:.3f}" for c in v) + ")"


def _bearing_state(params, seat, part, joint, stops: dict[str, list], poses, located, search) -> BearingState:
    """`stops`: per ring ("inner", "outer"), the parts that stand with its seat, among which its stops are found."""
    frame = geom.part_frame(poses, part)
    width = params.purchased(seat.key).num("width", positive=True)
    probe = _Probe(params, poses, frame, width, search)
    rings = {}
    for ring, seat_part in (("inner", seat.journal), ("outer", seat.housing)):
        radii = _annulus(params, seat.key, ring)
        sides = [probe.side(stops[ring], radii, sign, {part.name}) for sign in (-1, 1)]
        least, mean, most = fits.clearance(seat, params, ring)
        rings[ring] = Ring(ring, seat_part, seat.tolerance(ring), mean > 0, round(mean, 4), sides[0], sides[1])

    def held(side: Side) -> bool:
        return side.gap is not None and side.gap <= located

    inner, outer = rings["inner"], rings["outer"]
    stops = []
    if held(inner.minus) and held(outer.plus):
        stops.append("+axis")
    if held(inner.plus) and held(outer.minus):
        stops.append("-axis")
    role = {2: "fixed", 1: "one way", 0: "floating"}[len(stops)]
    axis = frame[:3, 2]
    centre = frame[:3, :3] @ np.array([0, 0, width / 2]) + frame[:3, 3]
    return BearingState(joint, part.name, seat.key, [round(float(c), 6) for c in axis],
                        [round(float(c), 4) for c in centre], role, stops, inner, outer)


def _gearhead_on_axis(params, parts_by_name, poses, joint, bearing: BearingState) -> tuple[str, np.ndarray] | None:
    """The joint's gearhead and its flange's centre (world) when its axis is the bearing's."""
    gear = parts_by_name.get(f"{joint}_gearhead")
    if gear is None:
        return None
    frame = geom.part_frame(poses, gear)
    axis, origin = np.array(bearing.axis), np.array(bearing.centre)
    if np.linalg.norm(np.cross(frame[:3, 2], axis)) > 1e-6:
        return None
    d = frame[:3, 3] - origin
    if np.linalg.norm(d - np.dot(d, axis) * axis) > ON_AXIS:
        return None
    return gear.name, frame[:3, 3]


def _check_floating(params, b: BearingState, fixed_at: np.ndarray, seat, located: float, by_name: dict) -> list[str]:
    problems = []
    axis = np.array(b.axis)
    b.span = round(abs(float(np.dot(np.array(b.centre) - fixed_at, axis))), 2)
    shaft, housing = by_name[seat.journal], by_name[seat.housing]
    need, growth, tol = required_float(params, b.span, (shaft.name, shaft.material), (housing.name, housing.material))
    b.required = round(need, 3)
    b.growth = f"{growth.shaft} shaft in {growth.housing} housing, {growth.governs} governs"
    sliding = b.ring(seat.sliding_ring)
    tight = b.ring(seat.tight_ring)
    where = f"{b.joint}: {b.bearing}"
    if not sliding.slides:
        problems.append(f"{where} floats on its {sliding.ring} ring, but that ring's fit {sliding.tolerance} holds it "
                        f"(mean interference {-sliding.mean_clearance * 1000:.1f} um): a floating ring needs a sliding fit")
    for label, side in (("-axis", sliding.minus), ("+axis", sliding.plus)):
        if side.gap is not None and side.gap < need:
            direction = _direction(axis if label == "+axis" else -axis)
            problems.append(f"{where} must float, but its {sliding.ring} ring ({sliding.tolerance}, the sliding one) has "
                            f"{side.gap:.2f} mm of room towards {direction} to {side.stop}: it needs {need:.2f} mm "
                            f"({growth.mm:.3f} of growth over {b.span:g} mm, {b.growth}, + {tol:g} ISO 2768-m)")
    if not any(side.gap is not None and side.gap <= located for side in (tight.minus, tight.plus)):
        problems.append(f"{where}: its tight {tight.ring} ring ({tight.tolerance}) sits against no shoulder")
    return problems


def ring_faces(params: HeadParameters, b: BearingState, by_name: dict, located: float) -> list[str]:
    """A retaining ring that bears on a bearing's ring (no shim between) must stay within that ring's face as fitted,
    or it rubs the shield or seal, which stands while the ring turns (or turns while it stands): a shaft ring's largest
    diameter (lug_outer_diameter, DIN's d3 max for a DIN 6799 washer) within the inner ring's face
    (inner_ring_outside), an internal ring's smallest (lug_inner_diameter) outside the outer ring's face's inner edge
    (outer_ring_inside, else the pitch circle)."""
    problems = []
    item = params.purchased(b.key)
    catalog = params.root.node("purchased")
    for ring, kind in ((b.inner, "shaft_ring"), (b.outer, "retaining_ring")):
        for side in (ring.minus, ring.plus):
            stop = by_name.get(side.stop)
            if side.gap is None or side.gap > located or side.through or stop is None or stop.kind != "purchased" \
                    or not catalog.has(stop.design) or params.purchased(stop.design).text("kind") != kind:
                continue
            fitted = params.purchased(stop.design)
            if kind == "shaft_ring":
                across, face = fitted.num("lug_outer_diameter", positive=True), item.num("inner_ring_outside")
                if across > face + 1e-9:
                    problems.append(f"{b.joint}: {stop.name} ({stop.design}, {across:g} across as fitted) bears on "
                                    f"{b.bearing}'s inner ring, whose face is {face:g} across ({b.key}): it reaches "
                                    f"onto its shield or seal; put a spacer between them or take a smaller ring")
            else:
                inside = fitted.num("lug_inner_diameter", positive=True)
                edge = face_edges(item)[1]
                if inside < edge - 1e-9:
                    problems.append(f"{b.joint}: {stop.name} ({stop.design}, its lugs in to {inside:g} as fitted) bears on "
                                    f"{b.bearing}'s outer ring, whose face starts at {edge:g} ({b.key}): it reaches "
                                    f"onto its shield or seal; put a shim between them")
    return problems


def face_edges(item) -> tuple[float, float]:
    """(inner ring's face outside, outer ring's face inside) in mm: where a bearing's seal or shield begins."""
    inside = item.num("outer_ring_inside") if item.has("outer_ring_inside") else \
        (item.num("bore") + item.num("outside")) / 2
    return item.num("inner_ring_outside", positive=True), inside


def shim_faces(params: HeadParameters, b: BearingState, by_name: dict, located: float) -> list[str]:
    """A shim that bears on a bearing's ring (the first of a stack, within located_within of the ring's face) must bear
    on that ring alone: beside the inner ring, its outside within the inner ring's face (inner_ring_outside, the maker's
    d1); beside the outer ring, its bore outside the outer ring's face's inner edge (outer_ring_inside, the maker's D2,
    else the pitch circle). Beyond that edge it lies on the seal or shield, which is fixed to the outer ring: a shim
    standing with one ring rubs it as the other turns, and one clamped on it presses it onto the balls' cage.
    Records each shim on b.shims; returns the problems."""
    problems = []
    item = params.purchased(b.key)
    inner_face, outer_face = face_edges(item)
    for ring in (b.inner, b.outer):
        for side in (ring.minus, ring.plus):
            if not side.through or side.shim_gap is None or side.shim_gap > located:
                continue
            part = by_name[side.through[0]]
            shim = params.purchased(part.design)
            bore, outside = shim.num("bore", positive=True), shim.num("outside", positive=True)
            if ring.ring == "inner":
                face, ok = (item.num("bore"), inner_face), outside <= inner_face + 1e-9
            else:
                face, ok = (outer_face, item.num("outside")), bore >= outer_face - 1e-9
            b.shims.append(ShimFace(part.name, part.design, ring.ring, bore, outside, face, ok))
            if ok:
                continue
            if ring.ring == "inner":
                problems.append(f"{b.joint}: {part.name} ({part.design}, {outside:g} across) bears on {b.bearing}'s "
                                f"inner ring, whose face is {inner_face:g} across ({b.key}): it reaches over the seal or "
                                f"shield; take a shim no more than {inner_face:g} across")
            else:
                problems.append(f"{b.joint}: {part.name} ({part.design}, its bore {bore:g}) bears on {b.bearing}'s "
                                f"outer ring, whose face starts at {outer_face:g} ({b.key}): it reaches in over the seal "
                                f"or shield; take a shim with a bore of at least {outer_face:g}")
    return problems


def analyse(params: HeadParameters, parts: list) -> Report:
    node = _node(params)
    located = node.num("located_within", positive=True)
    search = node.num("search", positive=True)
    gearhead_fixed = _joint_list(params, "gearhead_fixed")
    cross = _joint_list(params, "cross_located")
    poses = kinematics.link_poses(params, {})
    relevant = [p for p in parts if p.kind in ("machined", "purchased", "printed")]
    by_link: dict[str, list] = {}
    for p in relevant:
        by_link.setdefault(p.link, []).append(p)
    by_name = {p.name: p for p in relevant}
    seats = fits.seats(params, parts)
    shafts = jackshafts.find(params, parts, seats)
    shaft_of = {b: js for js in shafts for b in js.bearings}
    problems = []
    states: dict[str, list[BearingState]] = {}
    for name, seat in seats.items():
        if name in shaft_of:
            # a jackshaft turns in a housing of its own link: what turns with it holds the inner rings, what stands
            # on the link (the housing and what it is screwed to) the outer rings
            js = shaft_of[name]
            turning = [by_name[n] for n in js.turning if n in by_name]
            standing = [p for p in by_link[js.link] if p.name not in js.turning and p.name not in js.bearings]
            states.setdefault(js.shaft, []).append(_bearing_state(
                params, seat, by_name[name], js.shaft, {"inner": turning, "outer": standing}, poses, located, search))
            continue
        joint = _joint_of(params, by_name[seat.housing].link, by_name[seat.journal].link)
        if joint is None:
            problems.append(f"{name}: its housing {seat.housing} and journal {seat.journal} are not the two sides of a joint")
            continue
        stops = {"inner": by_link[by_name[seat.journal].link], "outer": by_link[by_name[seat.housing].link]}
        states.setdefault(joint, []).append(
            _bearing_state(params, seat, by_name[name], joint, stops, poses, located, search))
    joints = []
    # the chain's joints, then each jackshaft (fixed + floating)
    for joint in [j for j in CHAIN_JOINTS if j in states or j in gearhead_fixed] + [js.shaft for js in shafts]:
        bearings = states.get(joint, [])
        result = JointResult(joint, "", "", bearings)
        for b in bearings:
            result.problems += ring_faces(params, b, by_name, located)
            result.problems += shim_faces(params, b, by_name, located)
        fixed = [b for b in bearings if b.role == "fixed"]
        one_way = [b for b in bearings if b.role == "one way"]
        floating = [b for b in bearings if b.role == "floating"]
        if joint in cross:
            result.arrangement = "cross-located"
            result.fixed = " + ".join(b.bearing for b in one_way)
            if len(bearings) != 2 or len(one_way) != 2:
                result.problems.append(f"{joint}: a cross-located pair needs two bearings each locating one way; "
                                       + ", ".join(f"{b.bearing} is {b.role}" for b in bearings))
            elif np.dot(np.array(one_way[0].axis) * (1 if one_way[0].stops_shaft == ["+axis"] else -1),
                        np.array(one_way[1].axis) * (1 if one_way[1].stops_shaft == ["+axis"] else -1)) > 0:
                result.problems.append(f"{joint}: {one_way[0].bearing} and {one_way[1].bearing} both locate the shaft "
                                       f"the same way: nothing holds it the other way")
        elif joint in gearhead_fixed:
            result.arrangement = "gearhead + floating"
            gear = _gearhead_on_axis(params, by_name, poses, joint, bearings[0]) if bearings else None
            if bearings and gear is None:
                result.problems.append(f"{joint}: the gearhead is listed as the fixed bearing "
                                       f"(bearing_arrangement.gearhead_fixed) but {joint}_gearhead's axis is not the "
                                       f"shaft's ({bearings[0].bearing})")
            result.fixed = gear[0] if gear else f"{joint}_gearhead"
            for b in fixed + one_way:
                way = "both ways" if b.role == "fixed" else "one way"
                result.problems.append(f"{joint}: {b.bearing} locates the shaft {way} besides {result.fixed}'s output "
                                       f"bearings (the fixed bearing): they fight; it must float")
            if gear:
                for b in floating:
                    result.problems += _check_floating(params, b, gear[1], seats[b.bearing], located, by_name)
        else:
            result.arrangement = "fixed + floating"
            result.fixed = " + ".join(b.bearing for b in fixed)
            if not fixed:
                result.problems.append(f"{joint}: no bearing locates the shaft both ways (no fixed bearing): "
                                       + ", ".join(f"{b.bearing} is {b.role}" for b in bearings))
            elif len(fixed) > 1:
                result.problems.append(f"{joint}: {len(fixed)} fixed bearings ({', '.join(b.bearing for b in fixed)}) "
                                       f"locate the shaft: they fight as it grows; one must float")
            for b in one_way:
                way = _direction(np.array(b.axis) * (1 if b.stops_shaft == ["+axis"] else -1))
                result.problems.append(f"{joint}: {b.bearing} locates the shaft one way (towards {way}) besides the "
                                       f"fixed bearing: it must float")
            if len(fixed) == 1:
                for b in floating:
                    result.problems += _check_floating(params, b, np.array(fixed[0].centre), seats[b.bearing], located,
                                                       by_name)
        joints.append(result)
    return Report(located, search, joints, problems)


def _side_text(side: Side, search: float) -> str:
    text = f"free over {search:g} mm" if side.gap is None else f"{side.gap:.2f} mm to {side.stop}"
    return text + (f" (through {', '.join(side.through)})" if side.through else "")


def _shim_text(s: ShimFace) -> str:
    verdict = "bears on the ring alone" if s.ok else "reaches over the seal or shield"
    return f"    shim {s.shim} ({s.design}, {s.bore:g} x {s.outside:g}) on the {s.ring} ring, whose face is " \
           f"{s.face[0]:g} to {s.face[1]:g} across: {verdict}"


def format_report(report: Report) -> str:
    lines = [f"bearing arrangement: one fixed and one floating bearing per shaft (a ring is located by a stop within "
             f"{report.located_within:g} mm; rooms measured along each bearing's axis, up to {report.search:g} mm)"]
    for j in report.joints:
        lines.append(f"{j.joint}: {j.arrangement}; fixed: {j.fixed or 'none'}" + ("  FAIL" if j.problems else ""))
        for b in j.bearings:
            axis = np.array(b.axis)
            extra = f", {b.span:g} mm from the fixed bearing, needs {b.required:.2f} mm each way ({b.growth})" \
                if b.required is not None else ""
            stops = f", stops the shaft towards " + " and ".join(
                _direction(axis if s == "+axis" else -axis) for s in b.stops_shaft) if b.stops_shaft else ""
            lines.append(f"  {b.bearing} ({b.key}): {b.role}{stops}{extra}")
            for r in (b.inner, b.outer):
                fit = f"{r.tolerance}, {'slides' if r.slides else 'tight'} (mean {'clearance' if r.mean_clearance > 0 else 'interference'} " \
                      f"{abs(r.mean_clearance) * 1000:.1f} um)"
                lines.append(f"    {r.ring} ring on {r.seat}, {fit}: towards {_direction(-axis)} "
                             f"{_side_text(r.minus, report.search)}; towards {_direction(axis)} {_side_text(r.plus, report.search)}")
            lines += [_shim_text(s) for s in b.shims]
        for p in j.problems:
            lines.append(f"  PROBLEM {p}")
    for p in report.problems:
        lines.append(f"PROBLEM {p}")
    return "\n".join(lines)


def dumps(report: Report) -> str:
    return json.dumps({"ok": report.ok, "located_within_mm": report.located_within, "search_mm": report.search,
                       "joints": [asdict(j) for j in report.joints], "problems": report.failures}, indent=1)


def enforce(report: Report) -> None:
    if not report.ok:
        raise BearingArrangementError("bearing arrangement check failed: " + "; ".join(report.failures))
