# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The harness worked out from the parameters and the assembly: every cable's wires, ends, length and mating
parts; every free span's cut length from the kinematic sweep, and its bend radius and twist checked over the
joints' range of motion for each cable class that crosses it."""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field

import numpy as np

from robogene_head_model.params import CHAIN_JOINTS, HeadParameters, ParameterError

from .. import kinematics
from ..geom import exact_bounds
from . import pinout, spans
from .spec import HOST, CableClass, Clamp, HarnessSpec

LENGTH_STEP = 10.0   # cut lengths are rounded up to this (mm)


@dataclass
class ClassCheck:
    cls: str
    wires: int
    min_radius: float          # smallest bend radius over the sweep (mm)
    allowed_radius: float
    min_radius_pose: dict
    twist: float               # largest twist: deg/m (round) or edge strain (flat)
    allowed_twist: float
    min_inplane: float = math.inf   # flat cables
    allowed_inplane: float = 0.0
    problems: list[str] = field(default_factory=list)


@dataclass
class Span:
    a: str
    b: str
    joints: tuple[str, ...]
    poses: int
    max_chord: float
    length: float              # cut length of the free span (mm)
    checks: list[ClassCheck] = field(default_factory=list)
    cables: list[str] = field(default_factory=list)
    members: tuple[tuple[str, CableClass, int], ...] = ()     # (cable, class, wires) of each cable through it
    curves: list = field(default_factory=list, repr=False)   # the modelled cable at each pose of the sweep, in order


@dataclass
class CableRun:
    name: str
    cls: CableClass
    wires: tuple[str, ...]            # net per wire, pin 1 first
    source: tuple[str, str]           # board, connector ref
    source_mpn: str
    target: str                       # part, host or "board ref"
    target_mpn: str                   # the far board header's MPN, or ""
    via: tuple[str, ...]
    length: float                     # cut length (mm)


@dataclass
class CameraRun:
    name: str
    via: tuple[str, ...]
    required: float                   # mm
    length: float                     # the catalogue length chosen (mm)


@dataclass
class Harness:
    spec: HarnessSpec
    spans: dict[tuple[str, str], Span]
    cables: list[CableRun]
    cameras: list[CameraRun]
    problems: list[str]

    @property
    def ok(self) -> bool:
        return not self.problems


def _path_joints(params: HeadParameters, a: str, b: str) -> tuple[str, ...]:
    """The chain joints between links a and b (the kinematic tree is rooted at the neck base)."""
    parent = {params.joints[j].child: j for j in CHAIN_JOINTS}

    def up(link):
        out = []
        while link in parent:
            out.append(parent[link])
            link = params.joints[parent[link]].parent
        return out
    ua, ub = up(a), up(b)
    common = set(ua) & set(ub)
    return tuple(j for j in CHAIN_JOINTS if (j in ua or j in ub) and j not in common)


def frame(pose: np.ndarray, c: Clamp) -> spans.Frame:
    r = pose[:3, :3]
    return spans.Frame(r @ c.at + pose[:3, 3], r @ c.dir, r @ c.up)


def joint_angles(params: HeadParameters, joint: str, samples: int) -> np.ndarray:
    """A joint's sweep angles: `samples` evenly over its range, ends included (the checks look a span's curve up by
    them, so every sweep uses these)."""
    return np.linspace(params.joints[joint].lower, params.joints[joint].upper, int(samples))


def sweep(params: HeadParameters, joints: tuple[str, ...], samples: int):
    ranges = [joint_angles(params, j, samples) for j in joints]
    for values in itertools.product(*ranges):
        angles = dict(zip(joints, (float(v) for v in values)))
        yield angles, kinematics.link_poses(params, angles)


def swept_curves(params: HeadParameters, span: Span, a: Clamp, b: Clamp, samples: int) -> tuple[list, list]:
    """The span's own sweep ((angles, link poses) per pose) and its curve at each: the plan's, or (a span made by
    hand) the same curves worked out here."""
    swept = list(sweep(params, span.joints, samples))
    curves = span.curves or spans.curves([frame(p[a.link], a) for _, p in swept],
                                         [frame(p[b.link], b) for _, p in swept], span.length)
    return swept, curves


def check_span(params: HeadParameters, spec: HarnessSpec, a: Clamp, b: Clamp, users: list[tuple[str, CableClass, int]]) -> Span:
    """users: (cable name, class, wires) of every cable through the span."""
    joints = _path_joints(params, a.link, b.link)
    poses = list(sweep(params, joints, spec.sweep_samples))
    frames = [(angles, frame(p[a.link], a), frame(p[b.link], b)) for angles, p in poses]
    max_chord = max(float(np.linalg.norm(fb.at - fa.at)) for _, fa, fb in frames)
    given = {c.slack for c in (a, b) if c.slack is not None}
    if len(given) > 1:
        raise ParameterError(f"{params.path}: harness.clamps: {a.name} and {b.name} give the span between them "
                             f"different slacks ({', '.join(f'{v:g}' for v in sorted(given))})")
    slack = given.pop() if given else spec.free_slack
    length = math.ceil(max_chord * (1 + slack) / LENGTH_STEP * 2) * LENGTH_STEP / 2   # to 5 mm
    span = Span(a.name, b.name, joints, len(frames), max_chord, length, cables=[u[0] for u in users],
                members=tuple(users))
    try:
        span.curves = spans.curves([fa for _, fa, _ in frames], [fb for _, _, fb in frames], length)
    except ValueError as exc:
        where = f" at {_pose_text(frames[exc.pose][0])}" if getattr(exc, "pose", None) is not None else ""
        raise ParameterError(f"{params.path}: harness.clamps: span {a.name} -> {b.name}{where}: {exc}") from None
    shapes = [(angles, spans.measure(c, fb)) for (angles, _, fb), c in zip(frames, span.curves)]
    seen = set()
    for _, cls, wires in users:
        if (cls.name, wires) in seen:
            continue
        seen.add((cls.name, wires))
        worst = min(shapes, key=lambda s: s[1].min_radius)
        twist = max(abs(s.twist_deg) for _, s in shapes)
        check = ClassCheck(cls.name, wires, worst[1].min_radius, cls.min_bend_radius(wires), worst[0], 0.0, 0.0)
        where = f"span {a.name} -> {b.name} ({', '.join(joints)}; {length:g} mm free)"
        if check.min_radius < check.allowed_radius:
            check.problems.append(f"{where}: {cls.name} x{wires} bends to R {check.min_radius:.1f} mm at "
                                  f"{_pose_text(worst[0])}, its minimum is R {check.allowed_radius:.1f} mm "
                                  f"({cls.bend_factor:g} x {cls.od(wires):.2f} mm)")
        if cls.shape == "round":
            check.twist, check.allowed_twist = twist / length * 1000, cls.twist_deg_per_m
            if check.twist > check.allowed_twist + 1e-9:
                check.problems.append(f"{where}: {cls.name} twists {twist:.0f} deg ({check.twist:.0f} deg/m), its "
                                      f"limit is {cls.twist_deg_per_m:g} deg/m")
        else:
            half_width = cls.width / 2
            check.twist = math.sqrt(1 + (math.radians(twist) * half_width / length) ** 2) - 1
            check.allowed_twist = cls.edge_strain
            if check.twist > check.allowed_twist:
                check.problems.append(f"{where}: {cls.name} twists {twist:.0f} deg, straining its edges by "
                                      f"{check.twist:.2%}, its limit is {cls.edge_strain:.2%}")
            inplane = min(shapes, key=lambda s: s[1].min_inplane_radius)
            check.min_inplane, check.allowed_inplane = inplane[1].min_inplane_radius, cls.inplane_factor * cls.width
            if check.min_inplane < check.allowed_inplane:
                check.problems.append(f"{where}: {cls.name} bends in its own plane to R {check.min_inplane:.0f} mm at "
                                      f"{_pose_text(inplane[0])}, its limit is R {check.allowed_inplane:.0f} mm")
        span.checks.append(check)
    return span


def _pose_text(angles: dict) -> str:
    return ", ".join(f"{j} {v:+.1f}" for j, v in angles.items()) or "rest"


def _round_up(mm: float) -> float:
    return math.ceil(mm / LENGTH_STEP - 1e-9) * LENGTH_STEP


def plan(params: HeadParameters, spec: HarnessSpec, parts, connectors: dict | None = None) -> Harness:
    """parts: the assembly's parts (a cable's far end is the centre of its part, in that part's link)."""
    connectors = connectors if connectors is not None else pinout.connectors()
    by_name = {p.name: p for p in parts}
    b = params.root.node("boards")
    names = list(b.raw("names"))
    ox, oy, oz = b.vec("origin")
    pitch, thickness = b.num("stack_pitch"), b.num("thickness")

    def connector(board: str, ref: str, where: str):
        if ref not in connectors:
            raise ParameterError(f"{params.path}: {where}: the board has no connector {ref} "
                                 f"({', '.join(sorted(connectors))})")
        c = connectors[ref]
        level = names.index(board)
        return c, np.array([ox + c.centre[0], oy + c.centre[1], oz + level * pitch + thickness])

    def part_centre(name: str, where: str):
        if name not in by_name:
            raise ParameterError(f"{params.path}: {where}: no part {name!r} in the assembly")
        lo, hi = exact_bounds(by_name[name].shape)
        return by_name[name].link, (lo + hi) / 2

    def static(link: str, p: np.ndarray, q: np.ndarray) -> float:
        return float(np.linalg.norm(q - p)) * spec.routed_factor

    # Every free span and the cables through it.
    users: dict[tuple[str, str], list] = {}
    routes = [(c.name, c.cls, len(connectors[c.ref].nets) if c.ref in connectors else 0, c.via) for c in spec.cables]
    routes += [(c.name, spec.camera_class, 1, c.via) for c in spec.camera_cables]
    for name, cls, wires, via in routes:
        for x, y in zip(via, via[1:]):
            ca, cb = spec.clamps[x], spec.clamps[y]
            if ca.link == cb.link:
                continue
            key = (x, y) if (x, y) in users or (y, x) not in users else (y, x)
            users.setdefault(key, []).append((name, cls, wires))
    span_results = {}
    for (x, y), who in users.items():
        span_results[(x, y)] = check_span(params, spec, spec.clamps[x], spec.clamps[y], who)

    def through(via: tuple[str, ...], start: tuple[str, np.ndarray], end: tuple[str, np.ndarray] | None, where: str) -> float:
        """Length along start -> clamps -> end (end None: the host, past the bay exit)."""
        total, (link, p), prev = 0.0, start, None
        for name in via:
            c = spec.clamps[name]
            if prev is None and c.link != link:
                raise ParameterError(f"{params.path}: {where}: its first clamp {name} is on {c.link}, its start on {link}")
            if c.link == link:
                total += static(link, p, c.at)
            else:
                key = (prev, name) if (prev, name) in span_results else (name, prev)
                total += span_results[key].length
            link, p, prev = c.link, c.at, name
        if end is None:
            if link != "neck_base" or prev is None:
                raise ParameterError(f"{params.path}: {where}: a cable to the host leaves through the board bay: its "
                                     f"route must end at a neck_base clamp (the bay exit)")
            return total + spec.host_lead
        if end[0] != link:
            raise ParameterError(f"{params.path}: {where}: the route ends on {link} but its far end is on {end[0]}: "
                                 f"add the clamps that lead there")
        return total + static(link, p, end[1])

    runs = []
    problems = [p for s in span_results.values() for c in s.checks for p in c.problems]
    for i, c in enumerate(spec.cables):
        where = f"harness.cables[{i}] ({c.name})"
        src, p0 = connector(c.board, c.ref, where + ".from")
        target_mpn = ""
        if c.to == HOST:
            target, end = HOST, None
        elif isinstance(c.to, tuple):
            dst, p1 = connector(*c.to, where + ".to")
            if dst.pins != src.pins:
                raise ParameterError(f"{params.path}: {where}: {c.ref} has {src.pins} pins, {c.to[1]} {dst.pins}")
            target, end, target_mpn = f"{c.to[0]} {c.to[1]}", ("neck_base", p1), dst.mpn
        else:
            target, end = c.to, part_centre(c.to, where + ".to")
        if src.mpn not in spec.mating:
            raise ParameterError(f"{params.path}: harness.mating: no housing for {src.mpn} ({where})")
        length = through(c.via, ("neck_base", p0), end, where) + 2 * spec.service_loop
        runs.append(CableRun(c.name, c.cls, src.nets, (c.board, c.ref), src.mpn, target, target_mpn, c.via,
                             _round_up(length)))
    problems += brake_wiring_problems(params, runs)
    cams = []
    for i, c in enumerate(spec.camera_cables):
        where = f"harness.camera_cables.routes[{i}] ({c.name})"
        link, p = part_centre(c.camera, where + ".from")
        last = spec.clamps[c.via[-1]]   # the computer, where the cable ends
        required = through(c.via, (link, p), (last.link, last.at), where) + 2 * spec.service_loop
        fits = [v for v in spec.camera_lengths if v >= required]
        if not fits:
            problems.append(f"{where}: needs {required:.0f} mm, the longest camera cable is {max(spec.camera_lengths):g} mm")
        cams.append(CameraRun(c.name, c.via, round(required, 1), fits[0] if fits else math.nan))
    return Harness(spec, span_results, runs, cams, problems)


def brake_wiring_problems(params: HeadParameters, runs: list[CableRun]) -> list[str]:
    """Every holding brake (drives.<joint>.brake) needs a cable from the brake header of the board axis that drives
    its joint (+12V and that channel's switched return, M<n>_BRAKE_N) to the brake: unwired, the brake never
    releases and the joint cannot move."""
    boards = params.root.node("motor_control").raw("boards")
    out = []
    for joint in CHAIN_JOINTS:
        drive = params.drive(joint)
        if not drive.has("brake"):
            continue
        axis = next(((b["name"], b["axes"].index(joint)) for b in boards if joint in b["axes"]), None)
        if axis is None:
            out.append(f"{joint}: its brake {drive.text('brake')} is on no board axis (motor_control.boards)")
            continue
        want = ("+12V", f"M{axis[1] + 1}_BRAKE_N")
        cables = [r for r in runs if r.target == f"{joint}_brake"]
        if not cables:
            out.append(f"{joint}: its brake {drive.text('brake')} has no cable (harness.cables: from {axis[0]}'s "
                       f"header with {', '.join(want)} to {joint}_brake)")
        for r in cables:
            if r.source[0] != axis[0] or r.wires != want:
                out.append(f"harness cable {r.name}: {joint}_brake needs {axis[0]}'s header with {', '.join(want)}; "
                           f"{r.source[0]} {r.source[1]} carries {', '.join(r.wires)}")
    return out


def bom_lines(harness: Harness) -> list[tuple[str, float, str]]:
    """(catalog key, quantity per head, what for): housings and contacts at every crimped end, wire by the metre
    (each wire of a cable at the cable's cut length), one camera cable of the chosen length per eye."""
    out = []
    for run in harness.cables:
        ends = [run.source_mpn] + ([run.target_mpn] if run.target_mpn else [])
        for mpn in ends:
            housing, contact = harness.spec.mating[mpn]
            out.append((housing, 1, f"harness {run.name}"))
            out.append((contact, len([n for n in run.wires if n]), f"harness {run.name}"))
        out.append((run.cls.wire, round(run.length * len(run.wires) / 1000, 3), f"harness {run.name}"))
    for cam in harness.cameras:
        if cam.length in harness.spec.camera_lengths:
            out.append((harness.spec.camera_lengths[cam.length], 1, f"harness {cam.name}"))
    return out
