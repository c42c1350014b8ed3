# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Whether each free span's cables pass through the parts: the span's modelled curve (spans.py) over the sweep of
its joints, with its cables' cross-section round it, against every part of the assembly at that pose.

The round wires of a span are one bundle along the curve, of the diameter that holds their cross-sections at
PACKING (loose wires laid parallel fill about two thirds of the circle round them: spec.GROUP_FACTOR gives 0.65 to
0.69 for three to six wires); each flat cable is its own width x thickness band along the curve, turned with the
curve's carried frame. Near a clamp the cables lie on the part the clamp holds them to: within clamp_zone (mm, along
the curve) of a clamp, touching the parts of that clamp's link is not counted. Anything else the curve's cables
touch is a blocked route: a cable cannot be laid where a part is.

The curve is a model of where the cable hangs (a real cable rests on what it meets), so a span it passes through
a part in is a span whose clamps do not lead the cable past that part; a span clear of every part is one the cable
can take as modelled.

The sweep is the span's own joints' (harness.sweep_samples each) and, harness.near_samples each, the joints
harness.near_joints lists for them that the span does not cross: those move parts past the span without bending it
(a neck loop with the other neck joints turned, a loop across tilt with the eyes panned). The curve keeps its shape
in its first clamp's link and is carried with it.

A clamp is a clip or tie on a part's face: each must lie outside every part of its link and within clamp_standoff
(mm) of one of them that stands in the link, the part that holds it. A clamp inside a part, or further from every
standing part of its link, has nothing to hold it; the parts that turn in a link's own bearings (a jackshaft and the
coupling, pulley and screws on it: jackshafts.py) stand for no clamp.

The build stops on a blocked span or an unheld clamp (build.py), except for the spans harness.unresolved names,
each with why: those are reported as blocked and known. An entry whose span is clear, or is no span of the harness,
stops the build too, so the list cannot outlive the problem it names."""
from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import cadquery as cq
import fcl
import numpy as np

from robogene_head_model.params import HeadParameters, Node

from .. import fcl_mesh, jackshafts, kinematics
from . import spans
from .plan import Harness, Span, joint_angles, swept_curves
from .spec import Clamp

PACKING = 0.65            # share of a loose bundle's circle its wires fill
MESH_DEFLECTION = 0.1     # mm, the parts' tessellation
ON_FACE = 2 * MESH_DEFLECTION   # mm: a clamp this close to a part's mesh is on its face


@dataclass(frozen=True)
class Blocked:
    part: str
    link: str
    cable: str            # "bundle" (the round wires) or the flat cable's name
    at_mm: float          # along the span from its first clamp
    pose: dict[str, float]


@dataclass
class SpanClearance:
    a: str
    b: str
    bundle_od: float                       # mm, 0 without round wires
    flat: tuple[tuple[str, float, float], ...]   # (cable, width, thickness)
    poses: int
    blocked: list[Blocked] = field(default_factory=list)   # the first pose each part is met in, per cable

    @property
    def ok(self) -> bool:
        return not self.blocked


@dataclass(frozen=True)
class ClampSupport:
    name: str
    link: str
    nearest: str          # the nearest part of its link that stands in it ("" when none does)
    distance: float       # mm from that part's surface
    inside: str           # the part of its link it lies inside, or ""
    standoff: float

    @property
    def ok(self) -> bool:
        return not self.inside and self.distance <= self.standoff


@dataclass
class Clearance:
    clamp_zone: float
    spans: list[SpanClearance]
    clamps: list[ClampSupport] = field(default_factory=list)
    unresolved: dict[tuple[str, str], str] = field(default_factory=dict)   # (a, b): why it is still blocked
    crossings: list = field(default_factory=list)    # crossing.Crossing: spans whose cables run into each other

    @property
    def ok(self) -> bool:
        return not self.problems

    @property
    def known(self) -> list[str]:
        """The blocked spans harness.unresolved names: reported, not stopping the build."""
        return [line for s in self.spans if (s.a, s.b) in self.unresolved for line in _blocked_lines(s)]

    @property
    def problems(self) -> list[str]:
        out = []
        for c in self.clamps:
            if c.inside:
                out.append(f"clamp {c.name}: inside {c.inside} ({c.link}): nothing can hold a cable there")
            elif not c.nearest:
                out.append(f"clamp {c.name}: no part of {c.link} stands in the link to hold it")
            elif not c.ok:
                out.append(f"clamp {c.name}: {c.distance:.1f} mm from the nearest standing part of {c.link} "
                           f"({c.nearest}), more than clamp_standoff {c.standoff:g} mm: nothing holds it")
        for s in self.spans:
            if (s.a, s.b) not in self.unresolved:
                out += _blocked_lines(s)
            elif s.ok:
                out.append(f"span {s.a} -> {s.b}: clear of every part, but harness.unresolved still names it: take "
                           f"it off that list")
        return out + [x.text() for x in self.crossings]


def _blocked_lines(s: SpanClearance) -> list[str]:
    out = []
    for b in s.blocked:
        pose = ", ".join(f"{j} {v:+.1f}" for j, v in b.pose.items()) or "rest"
        what = f"the round wires (bundle {s.bundle_od:.1f} mm)" if b.cable == "bundle" else f"{b.cable}"
        out.append(f"span {s.a} -> {s.b}: {what} pass through {b.part} ({b.link}) {b.at_mm:.0f} mm from {s.a}, "
                   f"at {pose}")
    return out


def unresolved(params: HeadParameters, harness: Harness) -> dict[tuple[str, str], str]:
    """harness.unresolved: a list of {from, to, why}, each a free span of the harness."""
    node = params.root.node("harness")
    entries = node.raw("unresolved") if node.has("unresolved") else []
    if not isinstance(entries, list):
        raise node.fail("unresolved", f"expected a list of {{from, to, why}}, got {entries!r}")
    items = Node({f"unresolved[{i}]": e for i, e in enumerate(entries)}, "harness", str(params.path))
    out = {}
    for i in range(len(entries)):
        entry = items.node(f"unresolved[{i}]")
        key, why = (entry.text("from"), entry.text("to")), entry.text("why")
        if key not in harness.spans:
            raise items.fail(f"unresolved[{i}]", f"{key[0]} -> {key[1]} is no free span of the harness")
        if key in out:
            raise items.fail(f"unresolved[{i}]", f"{key[0]} -> {key[1]} is named twice")
        out[key] = why
    return out


def bundle_od(span: Span) -> float:
    """Diameter of the bundle of a span's round wires (mm): their cross-sections at PACKING."""
    area = 0.0
    for _, cls, wires in span.members:
        if cls.shape != "round":
            continue
        area += wires * cls.wire_od ** 2 if cls.laid == "loose" else cls.od(wires) ** 2
    return math.sqrt(area / PACKING) if area else 0.0


class _Models:
    """The parts as FCL meshes in their link frames: one per link to find a contact, one per part to name it."""

    def __init__(self, parts):
        self.parts = [p for p in parts if p.kind != "board"]   # the boards sit in the bay, below every span
        self.part_models, by_link = [], {}
        for p in self.parts:
            v, t = fcl_mesh.triangles(p.shape, MESH_DEFLECTION, 0.3)
            self.part_models.append(fcl_mesh.bvh(v, t))
            acc = by_link.setdefault(p.link, ([], [], 0))
            acc[0].append(v)
            acc[1].append(t + acc[2])
            by_link[p.link] = (acc[0], acc[1], acc[2] + len(v))
        self.links = {link: fcl_mesh.bvh(np.vstack(v), np.vstack(t)) for link, (v, t, _) in by_link.items()}


def basis(tangent: np.ndarray, width: np.ndarray) -> np.ndarray:
    """Rotation whose z is the tangent and x the width direction (the frame FCL's capsule and box are set in)."""
    z = tangent / np.linalg.norm(tangent)
    x = width - np.dot(width, z) * z
    x /= np.linalg.norm(x)
    return np.column_stack([x, np.cross(z, x), z])


def flat_cables(span: Span) -> tuple[tuple[str, float, float], ...]:
    """(cable, width, thickness) of each flat cable through the span."""
    return tuple((name, cls.width, cls.thickness) for name, cls, _ in span.members if cls.shape == "flat")


def sections(od: float, flats: Sequence[tuple[str, float, float]], seg: float) -> list[tuple[str, object]]:
    """The cables' cross-sections along one piece `seg` long, as FCL shapes in the piece's basis (z along it, x
    across a flat cable's width): the round wires' bundle as a capsule ("bundle"), each flat cable as its band."""
    out = [("bundle", fcl.Capsule(od / 2, seg))] if od else []
    return out + [(name, fcl.Box(w, t, seg)) for name, w, t in flats]


def _touches(obj, target) -> bool:
    return fcl.collide(obj, target, fcl.CollisionRequest(), fcl.CollisionResult()) > 0


def clamp_supports(harness: Harness, models: _Models, standoff: float,
                   turning: frozenset[str] = frozenset()) -> list[ClampSupport]:
    """turning: the parts that turn in their link's own bearings, which hold no clamp (a clamp may still not lie
    inside one)."""
    out = []
    for name, c in harness.spec.clamps.items():
        point = fcl.CollisionObject(fcl.Sphere(1e-3), fcl.Transform(c.at))
        nearest, distance, inside = "", math.inf, ""
        for part, model in zip(models.parts, models.part_models):
            if part.link != c.link:
                continue
            d = fcl.distance(point, fcl.CollisionObject(model, fcl.Transform()), fcl.DistanceRequest(),
                             fcl.DistanceResult())
            if d < distance and part.name not in turning:
                nearest, distance = part.name, max(d, 0.0)
            # FCL measures to the mesh's surface from either side: a point that far from the surface and within the
            # solid is inside it (on the face, where a clip sits, is not).
            if not inside and d > ON_FACE and part.shape.isInside(cq.Vector(*map(float, c.at)), 1e-3):
                inside = part.name
        out.append(ClampSupport(name, c.link, nearest, distance, inside, standoff))
    return out


def span_clearance(params: HeadParameters, span: Span, a: Clamp, b: Clamp, models: _Models, zone: float,
                   samples: int, near: dict[str, Sequence[float]] | None = None) -> SpanClearance:
    """One span's cables against the parts over its joints' sweep (`samples` per joint). near: joints the span does
    not cross to sweep as well (name: angles); the curve keeps its shape in clamp A's link frame whatever they do, and
    is carried along with it."""
    near = near or {}
    od = bundle_od(span)
    flats = flat_cables(span)
    sc = SpanClearance(a.name, b.name, od, flats, 0)
    seen: set[tuple[str, str]] = set()
    swept, curves = swept_curves(params, span, a, b, samples)
    for (own_angles, own), c in zip(swept, curves):
        for values in itertools.product(*near.values()):
            angles, poses, points, widths = own_angles, own, c.points, c.widths
            if near:
                angles = dict(own_angles, **dict(zip(near, values)))
                poses = kinematics.link_poses(params, angles)
                carry = poses[a.link] @ np.linalg.inv(own[a.link])
                points, widths = c.points @ carry[:3, :3].T + carry[:3, 3], c.widths @ carry[:3, :3].T
            sc.poses += 1
            s = spans.arc_lengths(c)
            links = {link: fcl.CollisionObject(m, fcl.Transform(poses[link][:3, :3], poses[link][:3, 3]))
                     for link, m in models.links.items()}
            for j in range(len(s) - 1):
                p, q = points[j], points[j + 1]
                seg = float(np.linalg.norm(q - p))
                mid_s = (s[j] + s[j + 1]) / 2
                exempt = {a.link} if mid_s < zone else set()
                exempt |= {b.link} if span.length - mid_s < zone else set()
                rot = basis(q - p, widths[j])
                for cable, geometry in sections(od, flats, seg):
                    obj = fcl.CollisionObject(geometry, fcl.Transform(rot, (p + q) / 2))
                    for link, target in links.items():
                        if link in exempt or not _touches(obj, target):
                            continue
                        for part, model in zip(models.parts, models.part_models):
                            if part.link != link or (part.name, cable) in seen:
                                continue
                            placed = fcl.CollisionObject(model, fcl.Transform(poses[link][:3, :3], poses[link][:3, 3]))
                            if _touches(obj, placed):
                                seen.add((part.name, cable))
                                sc.blocked.append(Blocked(part.name, link, cable, float(mid_s),
                                                          {k: round(v, 1) for k, v in angles.items()}))
    return sc


def near_joints(params: HeadParameters, joints: Sequence[str]) -> dict[str, np.ndarray]:
    """The joints harness.near_joints lists for a span crossing `joints`, but those, each at harness.near_samples
    angles over its range."""
    node = params.root.node("harness")
    table = node.node("near_joints")
    samples = node.num("near_samples", minimum=1)
    if samples != int(samples):
        raise node.fail("near_samples", f"expected a whole number of samples, got {samples!r}")
    near: set[str] = set()
    for joint in table.keys():
        if joint not in params.joints:
            raise table.fail(joint, "is no joint of the head")
    for own in joints:
        listed = table.raw(own) if table.has(own) else []
        if not isinstance(listed, list) or not all(isinstance(j, str) for j in listed):
            raise table.fail(own, f"expected a list of joint names, got {listed!r}")
        unknown = [j for j in listed if j not in params.joints]
        if unknown:
            raise table.fail(own, f"{unknown[0]!r} is no joint of the head")
        near.update(listed)
    return {j: joint_angles(params, j, samples) for j in sorted(near - set(joints))}


def turning_parts(params: HeadParameters, parts) -> frozenset[str]:
    """The parts that turn in their own link's bearings (jackshafts.find): no clamp holds to them."""
    return frozenset(name for shaft in jackshafts.find(params, list(parts)) for name in shaft.turning)


def check(params: HeadParameters, harness: Harness, parts,
          unresolved: dict[tuple[str, str], str] | None = None) -> Clearance:
    """unresolved: the spans known to be blocked, with why (the build passes harness.unresolved's, unresolved())."""
    node = params.root.node("harness")
    zone = node.num("clamp_zone", minimum=0)
    models = _Models(parts)
    results = [span_clearance(params, span, harness.spec.clamps[x], harness.spec.clamps[y], models, zone,
                              harness.spec.sweep_samples, near_joints(params, span.joints))
               for (x, y), span in harness.spans.items()]
    supports = clamp_supports(harness, models, node.num("clamp_standoff", positive=True),
                              turning_parts(params, parts))
    return Clearance(zone, results, supports, dict(unresolved or {}))
