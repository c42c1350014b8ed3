# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The joints' ball bearings against their basic static load rating C0: a check of the build.

For each joint under bearing_loads.joints, the bearings are found in the assembly (ball bearings whose axis is the
joint's axis) and they carry the body beyond the joint (the links past it, with the payloads of drive_sizing) at
every pose of a grid over all the joints' ranges, with and without the payloads:
  F = m (a - g)         the force the bearings put on the body: gravity and the acceleration of its centre of mass
  M = c x F + I alpha   the moment about the joint's origin
where a and alpha come from the angular accelerations of the joint and every joint before it (drive_sizing.
accelerations), each at its full value with either sign. The force along the axis is Fa; across it, the force and
the moment split into a radial load on each of two bearings by their places along the axis:
  R1 + R2 = F_radial,  t1 R1 + t2 R2 = M_radial x axis
SKF's equivalent static load of a deep-groove ball bearing, P0 = 0.6 Fr + 0.5 Fa and at least Fr (skf.com, deep
groove ball bearings, "Loads"), is charged with the whole Fa on each bearing, which ever of them locates that way;
C0 / P0 must reach bearing_loads.static_safety. A joint whose body tips on one bearing fails outright: a deep-groove
bearing has no moment rating and tilts within its internal clearance before it takes one.
A jackshaft's two bearings (jackshafts.find: a shaft turning in a housing of its own link, both found from the parts'
data) carry the belt's pull on its pulley at the drive's peak torque (torque_path.peak, at the gearhead's shaft, which
the jackshaft carries 1:1). The belt's effective tension is Te = T / r at the pulley's pitch radius; the installation
tension keeps the slack span at belt_slack_ratio x Te, so the tight span carries (1 + ratio) Te and the pull on the
shaft is at most the two spans' sum, (1 + 2 ratio) Te (the spans taken parallel: an upper bound). It acts in the
belt's plane, the middle of the pulley's width, and splits between the bearings by statics (the pulley overhangs the
outer one); the belt puts no axial load on them. The pulley's set screws press it onto the shaft: a force inside the
pulley and shaft, no load on the bearings. Each row is held against C0 like the joints' bearings.
Left out: the centripetal terms of the joints' speeds, the belt's pull on the yaw shaft, the jackshafts' own weight
(grams) and the gearheads' own output bearings on pitch and roll (their ratings are FAULHABER's, not in the parameter
file)."""
from __future__ import annotations

import itertools
import json
import math
from dataclasses import asdict, dataclass, field

import numpy as np

from robogene_head_model.params import CHAIN_JOINTS, HeadParameters, ParameterError

from . import drive_sizing, geom, jackshafts, kinematics, torque_path
from .parts import mounts
from .massprops import MassProps, combine

GRAVITY = 9.80665
ON_AXIS = 1e-3        # mm: a bearing's centre this close to the joint's axis sits on it
GRID = 5              # samples per joint over its range
TIPPING = 1e-6        # N m: less than this across the axis is no tipping moment


class BearingLoadError(RuntimeError):
    """A bearing below its static safety; the message is the table."""


@dataclass(frozen=True)
class BearingLoad:
    joint: str
    bearing: str          # the part's name
    key: str              # catalogue key
    at_mm: float          # along the joint's axis from its origin (a jackshaft's: from the belt's plane)
    c0_kN: float
    radial_N: float       # at the worst pose
    axial_N: float
    p0_N: float
    safety: float         # C0 / P0
    case: str
    pose: dict


@dataclass(frozen=True)
class Report:
    required: float
    loads: list[BearingLoad]
    problems: list[str]     # joints that cannot be checked as built (one bearing carrying a tipping moment)
    pulls: list = field(default_factory=list)   # BeltPull per jackshaft

    @property
    def ok(self) -> bool:
        return not self.problems and all(b.safety >= self.required for b in self.loads)


def _node(params: HeadParameters):
    return params.root.node("bearing_loads")


def required_safety(params: HeadParameters) -> float:
    return _node(params).num("static_safety", minimum=1.0)


def slack_ratio(params: HeadParameters) -> float:
    return _node(params).num("belt_slack_ratio", positive=True)


def checked_joints(params: HeadParameters) -> list[str]:
    joints = _node(params).raw("joints")
    if not isinstance(joints, list) or not all(j in CHAIN_JOINTS for j in joints):
        raise ParameterError(f"{params.path}: bearing_loads.joints: expected a list of chain joints "
                             f"({', '.join(CHAIN_JOINTS)}), got {joints!r}")
    return joints


def bearings_on_axis(params: HeadParameters, parts: list, joint: str) -> list[tuple[float, object]]:
    """(place along the joint's axis, part) of each ball bearing whose axis is the joint's, at the zero pose."""
    poses = kinematics.link_poses(params, {})
    origin, axis = kinematics.joint_axes_world(params, {})[joint]
    catalog = params.root.node("purchased")
    found = []
    for part in parts:
        if part.kind != "purchased" or not catalog.has(part.design) \
                or params.purchased(part.design).text("kind") != "bearing":
            continue
        pose = poses[part.link]
        centre = part.shape.Center()
        world = pose[:3, :3] @ np.array([centre.x, centre.y, centre.z]) + pose[:3, 3]
        d = world - origin
        off = d - np.dot(d, axis) * axis
        ring_axis = geom.part_frame(poses, part)[:3, 2]     # the bearing envelope's axis (its frame's z)
        if np.linalg.norm(off) < ON_AXIS and abs(abs(np.dot(ring_axis, axis)) - 1) < 1e-6:
            found.append((float(np.dot(d, axis)), part))
    return sorted(found, key=lambda f: f[0])


def _distal(params: HeadParameters, joint: str) -> list[str]:
    child = params.joints[joint].child
    out, todo = [], [child]
    while todo:
        link = todo.pop()
        out.append(link)
        todo += [params.joints[j].child for j in CHAIN_JOINTS if params.joints[j].parent == link]
    return out


def _upstream(params: HeadParameters, joint: str) -> list[str]:
    """The joint and every joint between it and the neck base."""
    by_child = {params.joints[j].child: j for j in CHAIN_JOINTS}
    out, link = [], params.joints[joint].child
    while link in by_child:
        j = by_child[link]
        out.append(j)
        link = params.joints[j].parent
    return out


def _grid(params: HeadParameters) -> list[dict[str, float]]:
    axes = [np.linspace(params.joints[j].lower, params.joints[j].upper, GRID) for j in CHAIN_JOINTS]
    return [dict(zip(CHAIN_JOINTS, map(float, q))) for q in itertools.product(*axes)
            if q[4] == q[5]]   # the two eye pans together: their share of the load is small


def _loads_at(params, props, joint, distal, upstream, accels, q):
    """(axial force N, radial force vector N, radial moment about the origin N m, axis) in the joint's child frame,
    the worst over the accelerations' signs is left to the caller: one entry per sign combination."""
    poses = kinematics.link_poses(params, q)
    frame = poses[params.joints[joint].child]
    inv = np.linalg.inv(frame)
    body = combine([props[link].moved(inv @ poses[link]) for link in distal if link in props])
    m, c, inertia = body.mass, body.com * 1e-3, body.inertia * 1e-6
    rot = frame[:3, :3]
    g = rot.T @ np.array([0.0, 0.0, -GRAVITY])
    axis = np.array(params.joints[joint].axis, dtype=float)
    terms = []
    for j in upstream:
        pose = inv @ poses[params.joints[j].child]
        u = pose[:3, :3] @ np.array(params.joints[j].axis, dtype=float)
        p = pose[:3, 3] * 1e-3
        terms.append((accels[j] * u, accels[j] * np.cross(u, c - p)))
    out = []
    for signs in itertools.product((1.0, -1.0), repeat=len(terms)):
        alpha = sum(s * t[0] for s, t in zip(signs, terms))
        acc = sum(s * t[1] for s, t in zip(signs, terms))
        force = m * (acc - g)
        moment = np.cross(c, force) + inertia @ alpha
        axial = float(np.dot(force, axis))
        out.append((axial, force - axial * axis, moment - np.dot(moment, axis) * axis, axis))
    return out


def analyse(params: HeadParameters, parts: list, props: dict[str, MassProps]) -> Report:
    required = required_safety(params)
    cases = {"bare": props, "loaded": drive_sizing.with_payloads(params, props)}
    grid = _grid(params)
    loads, problems = [], []
    for joint in checked_joints(params):
        on_axis = bearings_on_axis(params, parts, joint)
        distal, upstream = _distal(params, joint), _upstream(params, joint)
        accels = {j: math.radians(drive_sizing.acceleration(params, j)) for j in upstream}
        worst: dict[str, tuple] = {}
        tipping = 0.0
        for case, mp in cases.items():
            for q in grid:
                for axial, force, moment, axis in _loads_at(params, mp, joint, distal, upstream, accels, q):
                    tipping = max(tipping, float(np.linalg.norm(moment)))
                    if len(on_axis) != 2:
                        continue
                    (t1, _), (t2, _) = on_axis
                    t1, t2 = t1 * 1e-3, t2 * 1e-3
                    w = np.cross(moment, axis)
                    r2 = (w - t1 * force) / (t2 - t1)
                    r1 = force - r2
                    for (t, part), r in zip(on_axis, (r1, r2)):
                        fr = float(np.linalg.norm(r))
                        p0 = max(fr, 0.6 * fr + 0.5 * abs(axial))
                        if part.name not in worst or p0 > worst[part.name][2]:
                            worst[part.name] = (fr, axial, p0, case, q)
        if len(on_axis) < 2:
            if tipping > TIPPING:
                problems.append(f"{joint}: {len(on_axis)} ball bearing on its axis carries a tipping moment of up to "
                                f"{tipping:.2f} N m: a deep-groove bearing has no moment rating (it tilts within its "
                                f"clearance first); it needs two, spaced along the axis")
            continue
        if len(on_axis) > 2:
            problems.append(f"{joint}: {len(on_axis)} ball bearings on its axis: the check splits the load over two")
            continue
        if abs(on_axis[1][0] - on_axis[0][0]) < 1e-6:
            problems.append(f"{joint}: its two bearings sit at the same place along the axis")
            continue
        for t, part in on_axis:
            fr, axial, p0, case, q = worst[part.name]
            c0 = params.purchased(part.design).num("static_load_rating_kN", positive=True)
            loads.append(BearingLoad(joint, part.name, part.design, t, c0, fr, abs(axial), p0, c0 * 1e3 / p0, case,
                                     {k: round(v, 3) for k, v in q.items()}))
    jack_loads, jack_problems, pulls = jackshaft_loads(params, parts)
    return Report(required, loads + jack_loads, problems + jack_problems, pulls)


@dataclass(frozen=True)
class BeltPull:
    shaft: str
    joint: str
    torque_Nm: float         # the drive's peak torque on the jackshaft
    pitch_radius_mm: float
    effective_N: float       # Te = T / r
    pull_N: float            # on the shaft: (1 + 2 slack ratio) Te
    belt_at_mm: float        # the belt's plane along the shaft's axis


def belt_pull(params: HeadParameters, parts: list, shaft: jackshafts.Jackshaft) -> BeltPull:
    """The belt's pull on a jackshaft's pulley at its drive's peak torque, and where along the axis it acts."""
    by_name = {p.name: p for p in parts}
    stage = mounts.stage(params, shaft.joint)
    radius = mounts.pitch_diameter(params, shaft.joint, int(stage.num("motor_teeth", positive=True))) / 2
    torque = torque_path.peak(params, shaft.joint).at_gearhead
    effective = torque / (radius * 1e-3)
    pulley = jackshafts.frame(params, by_name[shaft.pulley])
    # the pulley's frame: its body along +z from its inner flange face; the belt runs in the middle of its width
    plane = pulley[:3, :3] @ np.array([0.0, 0.0, mounts.pulley_width(params, shaft.joint) / 2]) + pulley[:3, 3]
    return BeltPull(shaft.shaft, shaft.joint, torque, radius, effective,
                    (1 + 2 * slack_ratio(params)) * effective, shaft.along(plane))


def jackshaft_loads(params: HeadParameters, parts: list) -> tuple[list[BearingLoad], list[str], list[BeltPull]]:
    """Each jackshaft's two bearings under the belt's pull."""
    by_name = {p.name: p for p in parts}
    loads, problems, pulls = [], [], []
    for shaft in jackshafts.find(params, parts):
        if shaft.joint is None or shaft.pulley is None:
            problems.append(f"{shaft.shaft}: a jackshaft with " + ("no gearhead on its axis" if shaft.joint is None
                            else "not one pulley turning with it") + ": its belt's pull cannot be found")
            continue
        if len(shaft.bearings) != 2:
            problems.append(f"{shaft.shaft}: {len(shaft.bearings)} ball bearings: the check splits the belt's pull over two")
            continue
        pull = belt_pull(params, parts, shaft)
        pulls.append(pull)
        at = []
        for name in shaft.bearings:
            part = by_name[name]
            width = params.purchased(part.design).num("width", positive=True)
            centre = jackshafts.frame(params, part)[:3, :] @ np.array([0.0, 0.0, width / 2, 1.0])
            at.append(shaft.along(centre))
        (t1, t2), tb = at, pull.belt_at_mm
        if abs(t2 - t1) < 1e-6:
            problems.append(f"{shaft.shaft}: its two bearings sit at the same place along the axis")
            continue
        r2 = pull.pull_N * (tb - t1) / (t2 - t1)
        for name, t, r in zip(shaft.bearings, at, (pull.pull_N - r2, r2)):
            part = by_name[name]
            c0 = params.purchased(part.design).num("static_load_rating_kN", positive=True)
            fr = abs(r)
            # no axial load: P0 = max(Fr, 0.6 Fr) = Fr
            loads.append(BearingLoad(shaft.shaft, name, part.design, round(t - tb, 3), c0, fr, 0.0, fr, c0 * 1e3 / fr,
                                     f"belt pull {pull.pull_N:.1f} N", {}))
    return loads, problems, pulls


def format_table(report: Report) -> str:
    lines = [f"Bearing loads: worst case over the whole range, required static safety C0/P0 >= {report.required:g}",
             "joint / shaft        bearing                               at (mm)  C0 (kN)  Fr (N)  Fa (N)  P0 (N)  C0/P0  case",
             ]
    for b in report.loads:
        flag = "ok" if b.safety >= report.required else "TOO SMALL"
        lines.append(f"{b.joint:<20} {b.bearing:<37} {b.at_mm:7.1f} {b.c0_kN:8.3f} {b.radial_N:7.1f} {b.axial_N:7.1f} "
                     f"{b.p0_N:7.1f} {b.safety:6.1f}  {b.case} {flag}")
    for p in report.pulls:
        lines.append(f"{p.shaft}: the {p.joint} belt's pull (1 + 2 x slack ratio) x {p.torque_Nm:.3f} N m / "
                     f"{p.pitch_radius_mm:.2f} mm = {p.pull_N:.1f} N (Te {p.effective_N:.1f} N), no axial load; "
                     f"at (mm) from the belt's plane")
    lines += [f"FAIL {p}" for p in report.problems]
    return "\n".join(lines)


def dumps(report: Report) -> str:
    return json.dumps({"required_static_safety": report.required, "ok": report.ok, "problems": report.problems,
                       "bearings": [dict(asdict(b), ok=b.safety >= report.required) for b in report.loads],
                       "belt_pulls": [asdict(p) for p in report.pulls]}, indent=1)


def enforce(report: Report) -> None:
    if not report.ok:
        low = ", ".join(f"{b.bearing} ({b.safety:.2f})" for b in report.loads if b.safety < report.required)
        raise BearingLoadError("bearings below their static safety or unable to carry their load"
                               + (f": {low}" if low else "") + "\n" + format_table(report))
