# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Interference and clearance over a sweep of every joint's range.

Two parts interfere when their common volume exceeds VOLUME_TOLERANCE. Parts on different links that touch
(distance below the fit tolerance) must be a declared fit (a bearing on its shaft, a pulley on its shaft...);
any other contact or overlap is a failure.

Speed: every part is meshed once (chordal deviation MESH_DEFLECTION) and FCL measures mesh-to-mesh distances
in each pose. The true (B-rep) distance is within 2 x MESH_DEFLECTION of the mesh distance, so a pair whose
mesh distance is larger than that plus the fit tolerance cannot touch; only the others go to the exact
OpenCASCADE distance and boolean. A pair's result depends only on the relative pose of its two links, so
results are cached by that pose.
"""
from __future__ import annotations

import fnmatch
import itertools
from dataclasses import dataclass, field

import cadquery as cq
import fcl
import numpy as np

from robogene_head_model.params import CONTROL_JOINTS, HeadParameters

from .. import fcl_mesh, geom
from ..geom import location
from ..assembly import Assembly, Placed

VOLUME_TOLERANCE = 0.5   # mm^3: below this a common volume is boolean noise on touching faces
NEAR = 5.0               # mm: closest approaches above this are not reported
MESH_DEFLECTION = 0.05   # mm

# Designed contacts between parts on different links: (pattern, pattern). A fit is where two links meet.
FITS = [
    ("neck_pitch_bearing_*", "neck_pitch_stage"),
    ("neck_pitch_gearhead", "neck_pitch_stage"),
    ("neck_roll_bearing_*", "neck_roll_stage"),
    ("neck_roll_gearhead", "neck_roll_stage"),
    ("neck_pitch_hub_screw_*", "neck_pitch_gearhead"),   # the set screws' points on the gearhead's shaft
    ("neck_roll_hub_screw_*", "neck_roll_gearhead"),
    ("neck_yaw_bearing_*", "neck_roll_stage"),
    ("neck_yaw_spacer_*", "neck_yaw_bearing_*"),    # the spacer rings on the shaft against the inner rings
    ("eyes_tilt_bearing_*", "eyes_tilt_frame"),
    ("eyes_tilt_clip", "eyes_tilt_bearing_right"),   # the clip on the journal against the fixed bearing's inner ring
    ("*_eye_pan_gearhead", "*_eye_hub"),              # the hub's bore on the pan shaft
    ("*_eye_pan_gearhead", "*_eye_hub_set_screw_*"),  # and its set screws' points
    ("neck_yaw_belt", "neck_yaw_joint_pulley"),     # the belt runs on the pulley of the other link
    ("eyes_tilt_belt", "eyes_tilt_joint_pulley"),
]


def is_fit(a: str, b: str) -> bool:
    return any((fnmatch.fnmatch(a, p) and fnmatch.fnmatch(b, q)) or (fnmatch.fnmatch(b, p) and fnmatch.fnmatch(a, q))
               for p, q in FITS)


def sweep_poses(params: HeadParameters, samples: int = 5) -> list[dict[str, float]]:
    """Each control joint over its range with the others at zero, then every corner of the neck and tilt ranges
    with the eyes alternately fully converged to one side and parallel to the other."""
    poses = [{}]
    for name in CONTROL_JOINTS:
        lo, hi = params.control_limits[name]
        for k in range(samples):
            poses.append({name: lo + (hi - lo) * k / (samples - 1)})
    lim = params.control_limits
    eyes = [(lim["eyes_version"][0], lim["eyes_vergence"][1]), (lim["eyes_version"][1], lim["eyes_vergence"][0])]
    corners = itertools.product(*[lim[n] for n in ("neck_pitch", "neck_roll", "neck_yaw", "eyes_tilt")])
    for k, (p, r, y, t) in enumerate(corners):
        vs, vg = eyes[k % 2]
        poses.append({"neck_pitch": p, "neck_roll": r, "neck_yaw": y, "eyes_tilt": t,
                      "eyes_version": vs, "eyes_vergence": vg})
    return poses


@dataclass
class PairResult:
    a: str
    b: str
    distance: float | None      # None: further apart than NEAR
    overlap: float = 0.0        # common volume, mm^3
    pose: dict = field(default_factory=dict)


@dataclass
class Report:
    poses: int
    pairs_checked: int
    interferences: list[PairResult]
    undeclared_contacts: list[PairResult]
    clearances: dict[tuple[str, str], PairResult]   # closest approach per moving pair over the sweep
    minimum: float = 0.0                             # wanted clearance between moving parts

    @property
    def low(self) -> list[PairResult]:
        return sorted((r for r in self.clearances.values() if r.distance < self.minimum), key=lambda r: r.distance)

    @property
    def ok(self) -> bool:
        return not self.interferences and not self.undeclared_contacts and not self.low


class _Meshes:
    """FCL models of every part in its link frame, built once, and the meshed copies the exact distance is measured on
    (as fast whether or not the build exported the part before, fcl_mesh.meshed_copy)."""

    def __init__(self, parts):
        self.models, self.vertices, self.copies = [], [], []
        for part in parts:
            copy, v, t = fcl_mesh.meshed_copy(part.shape, MESH_DEFLECTION, 0.2)
            self.models.append(fcl_mesh.bvh(v, t))
            self.vertices.append(v)
            self.copies.append(copy)

    def exact(self, i: int, placed: Placed) -> cq.Shape:
        """Part i's meshed copy where `placed` puts it."""
        return self.copies[i].moved(location(placed.world))

    def objects(self, placed):
        out, boxes = [], []
        for i, p in enumerate(placed):
            rot, trans = p.world[:3, :3], p.world[:3, 3]
            out.append(fcl.CollisionObject(self.models[i], fcl.Transform(rot, trans)))
            w = self.vertices[i] @ rot.T + trans
            boxes.append((w.min(axis=0), w.max(axis=0)))
        return out, boxes


def check(params: HeadParameters, assembly: Assembly, poses=None, progress=None,
          static_checked_elsewhere: frozenset[str] = frozenset()) -> Report:
    """static_checked_elsewhere: parts whose pairs within their own link another check has measured (the mated plugs:
    checks/board_bay.py), so the sweep measures them only against parts that move relative to them."""
    poses = poses if poses is not None else sweep_poses(params)
    fit_tol = params.geometry("clearances").num("fit_tolerance", positive=True)
    exact_below = params.geometry("clearances").num("minimum", positive=True) + 2 * MESH_DEFLECTION
    meshes = _Meshes(assembly.parts)
    cache: dict = {}
    interferences, contacts, clearances = [], [], {}
    checked = 0
    links = [p.link for p in assembly.parts]
    # Two parts of one link never move relative to each other: they are checked in the first pose only.
    names = [p.name for p in assembly.parts]
    pairs_first = [(i, j) for i, j in itertools.combinations(range(len(links)), 2)
                   if links[i] != links[j] or not {names[i], names[j]} & static_checked_elsewhere]
    pairs_moving = [(i, j) for i, j in pairs_first if links[i] != links[j]]
    for index, pose in enumerate(poses):
        if progress:
            progress(index, len(poses))
        placed = assembly.pose(pose)
        objects, boxes = meshes.objects(placed)
        for i, j in pairs_first if index == 0 else pairs_moving:
            pa, pb = placed[i], placed[j]
            gap = np.maximum(boxes[i][0], boxes[j][0]) - np.minimum(boxes[i][1], boxes[j][1])
            if np.any(gap > NEAR):
                continue
            rel = np.round(np.linalg.inv(pa.world) @ pb.world, 6)
            key = (i, j, rel.tobytes())
            if key not in cache:
                checked += 1
                cache[key] = _pair(meshes.exact(i, pa), meshes.exact(j, pb), objects[i], objects[j], fit_tol,
                                   exact_below)
            dist, overlap = cache[key]
            if dist is None:
                continue
            moving = pa.part.link != pb.part.link
            fit = is_fit(pa.part.name, pb.part.name)
            result = PairResult(pa.part.name, pb.part.name, dist, overlap, pose)
            if overlap > VOLUME_TOLERANCE:
                interferences.append(result)
            elif moving and dist < fit_tol and not fit:
                contacts.append(result)
            if moving and not fit:
                name = (pa.part.name, pb.part.name)
                if name not in clearances or dist < clearances[name].distance:
                    clearances[name] = result
    minimum = params.geometry("clearances").num("minimum", positive=True)
    return Report(len(poses), checked, _unique(interferences), _unique(contacts), clearances, minimum)


def _pair(a: cq.Shape, b: cq.Shape, oa, ob, fit_tol: float, exact_below: float):
    """(distance or None when above NEAR, common volume). Near the wanted minimum clearance the distance is
    measured exactly, so a LOW verdict never rests on the mesh approximation."""
    mesh_dist = geom.mesh_distance(oa, ob)
    if mesh_dist > NEAR + 2 * MESH_DEFLECTION:
        return None, 0.0
    if mesh_dist > max(fit_tol + 2 * MESH_DEFLECTION, exact_below):
        return mesh_dist, 0.0     # certainly apart: the mesh distance is the clearance to +-0.1 mm
    dist = geom.distance(a, b)
    overlap = a.intersect(b).Volume() if dist < fit_tol else 0.0
    return dist, overlap


def _unique(results: list[PairResult]) -> list[PairResult]:
    seen, out = set(), []
    for r in results:
        if (r.a, r.b) not in seen:
            seen.add((r.a, r.b))
            out.append(r)
    return out


def format_report(report: Report, minimum: float) -> str:
    lines = [f"interference check: {report.poses} poses, {report.pairs_checked} pair evaluations",
             f"interferences: {len(report.interferences)}"]
    for r in report.interferences:
        lines.append(f"  INTERFERENCE {r.a} x {r.b}: {r.overlap:.2f} mm^3 at {r.pose}")
    lines.append(f"undeclared contacts between moving parts: {len(report.undeclared_contacts)}")
    for r in report.undeclared_contacts:
        lines.append(f"  CONTACT {r.a} x {r.b}: {r.distance:.3f} mm at {r.pose}")
    lines.append(f"closest approach of moving pairs under {NEAR} mm (minimum wanted {minimum} mm; distances from "
                 f"meshes are within {2 * MESH_DEFLECTION} mm of the exact value):")
    for (a, b), r in sorted(report.clearances.items(), key=lambda kv: kv[1].distance):
        flag = "  LOW" if r.distance < minimum else ""
        lines.append(f"  {r.distance:7.3f} mm  {a} x {b}  at {r.pose}{flag}")
    return "\n".join(lines)


def report_json(report: Report, minimum: float) -> dict:
    def row(r: PairResult) -> dict:
        return {"a": r.a, "b": r.b, "distance_mm": r.distance, "overlap_mm3": r.overlap, "pose": r.pose}
    return {"ok": report.ok, "poses": report.poses, "low_clearances": [row(r) for r in report.low], "pair_evaluations": report.pairs_checked,
            "minimum_clearance_wanted_mm": minimum,
            "interferences": [row(r) for r in report.interferences],
            "undeclared_contacts": [row(r) for r in report.undeclared_contacts],
            "declared_fits": [list(f) for f in FITS],
            "closest_approach": [row(r) for r in sorted(report.clearances.values(), key=lambda r: r.distance)]}
