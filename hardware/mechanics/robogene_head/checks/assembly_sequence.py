# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Prove the assembly sequence possible, step by step, at the zero pose.

Insertion. A step's parts travel along their path (straight moves between waypoints) from a start outside
everything already assembled in their context (bounding boxes apart) to their place. The sweep is
conservative advancement: at each sample the distance d from the moving parts to every part already in place
is a lower bound (mesh distance less twice the mesh's chordal deviation, or the gap between bounding boxes),
and in a pure translation no point moves further than the step, so stepping by d cannot pass through anything.
Where d falls under MIN_STEP the step is MIN_STEP and the distance is measured exactly (OpenCASCADE): a wall
could only be skipped if it were thinner than MIN_STEP (0.2 mm); the thinnest wall in the head is the 0.6 mm
pulley flange. Touching a part that is not declared a fit or a guide of the step is a failure while moving,
and allowed only at the final place (a part seats on its neighbours), where it must not overlap.
Declared fits and guides (a shaft in a bearing, a part sliding on a plate) may touch all along the path; they
are sampled every FIT_STEP and fail when they share more than VOLUME_TOLERANCE. The KiCad boards are measured on
their meshes only (see _Checker._exact_at): a standoff's stud through a board's hole is a declared fit whose
overlap is not measured; the fastener tests check the stack's studs and screws in place.

Screws. Each screw goes in along its axis: a cylinder of its head's diameter (a set screw's own, from its socket) from the head outwards, and the
driver's blade and then its handle beyond the blade's length, must be clear of everything in place until they
leave the bounding box of the assembly so far. Pressed parts: the path is one straight move along the part's axis and
the tool behind it must be clear likewise: an arbor (the part's diameter less 1 mm) behind a pin or a bearing pressed
into its housing by its outer ring, a sleeve over the journal on the inner ring of a bearing pressed onto its journal.

Tight rings. A bearing's ring that turns against the load has the tight fit (fits.seats); it goes onto its seat only
in a press step whose tool bears on that ring (press: inner or outer). A step that moves a bearing onto its tight
seat, or a tight seat into a bearing already in place, would push that ring through the balls and fails. Flexible
parts (belts, circlips) are placed by hand, not swept; a circlip's pliers get the same access check (an external
ring's pliers go round the shaft it sits on, which the step names under access.straddles).
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field

import cadquery as cq
import fcl
import numpy as np

from .. import fcl_mesh
from .. import fits as fits_mod
from ..assembly import Assembly, Placed
from .. import geom
from ..geom import location, matrix as placement_matrix
from ..sequence import Sequence, Step

MESH_DEFLECTION = 0.1      # mm: chordal deviation of the meshes; a mesh distance is within 2x of the true one
MIN_STEP = 0.2             # mm: smallest advance along a path (see above)
FIT_STEP = 1.0             # mm: sampling of declared fits and guides, under the thinnest wall (0.6 mm flange + ring)
VOLUME_TOLERANCE = 0.5     # mm^3: common volume below this is boolean noise on touching faces
TOUCH = 0.01               # mm: closer than this is touching
OUTSIDE_MARGIN = 5.0       # mm: a tool reaches this far beyond the assembly's bounding box
SLEEVE_CLEARANCE = 0.25    # mm: a press sleeve's bore over the journal's diameter, its wall within the inner ring's face


class AssemblyCheckError(RuntimeError):
    pass


@dataclass
class Problem:
    step: str
    what: str

    def __str__(self) -> str:
        return f"{self.step}: {self.what}"


@dataclass
class StepResult:
    label: str
    context: str
    parts: list[str]
    name: str = ""
    picture: str = ""                  # its picture's file name (render_steps draws it)
    path_length: float = 0.0
    samples: int = 0
    closest: float | None = None       # closest approach to a non-fit part while moving (mm)
    closest_to: str = ""
    tools: list[dict] = field(default_factory=list)
    note: str = ""
    problems: list[Problem] = field(default_factory=list)


@dataclass
class Report:
    steps: list[StepResult]
    seconds: float        # wall clock
    cpu_seconds: float    # this process's CPU time: what the check costs on a machine others share

    @property
    def problems(self) -> list[Problem]:
        return [p for s in self.steps for p in s.problems]

    @property
    def ok(self) -> bool:
        return not self.problems


class _World:
    """Every part at the zero pose: world shapes, meshes for FCL and bounding boxes, built once."""

    def __init__(self, assembly: Assembly):
        self.placed: dict[str, Placed] = {p.part.name: p for p in assembly.pose({})}
        self.models, self.boxes, self.frames, self.copies = {}, {}, {}, {}
        for name, p in self.placed.items():
            # measured on a meshed copy: as fast whether or not the build exported the part before (a cached STL)
            self.copies[name], vertices, triangles = fcl_mesh.meshed_copy(p.shape, MESH_DEFLECTION, 0.3)
            self.models[name] = fcl_mesh.bvh(vertices, triangles)
            # From the geometry alone: BoundingBox() bounds a triangulation when the part has one (the assembly's GLB
            # export meshes every part when the geometry changed), and the check would depend on that.
            self.boxes[name] = geom.exact_bounds(p.shape)
            self.frames[name] = p.world @ placement_matrix(p.part.placement)

    def obj(self, name: str, offset=np.zeros(3)) -> fcl.CollisionObject:
        return fcl.CollisionObject(self.models[name], fcl.Transform(np.eye(3), np.asarray(offset, dtype=float)))

    def shape(self, name: str, offset=np.zeros(3)) -> cq.Shape:
        s = self.copies[name]
        return s.moved(cq.Location(cq.Vector(*offset))) if np.any(offset) else s

    def bbox(self, names, offset=np.zeros(3)):
        lo = np.min([self.boxes[n][0] for n in names], axis=0) + offset
        hi = np.max([self.boxes[n][1] for n in names], axis=0) + offset
        return lo, hi


def _box_gap(a, b) -> float:
    gap = np.maximum(0.0, np.maximum(a[0] - b[1], b[0] - a[1]))
    return float(np.linalg.norm(gap))


def _near(shape: cq.Shape, other: cq.Shape, reach: float) -> list[cq.Shape]:
    """The solids of `shape` within `reach` of `other`'s bounding box: a board's hundreds of component models are
    measured only where they are near."""
    solids = shape.Solids()
    if len(solids) <= 1:
        return [shape]
    ob = other.BoundingBox()
    box = (np.array([ob.xmin, ob.ymin, ob.zmin]) - reach, np.array([ob.xmax, ob.ymax, ob.zmax]) + reach)
    out = []
    for s in solids:
        b = s.BoundingBox()
        if _box_gap((np.array([b.xmin, b.ymin, b.zmin]), np.array([b.xmax, b.ymax, b.zmax])), box) <= 0:
            out.append(s)
    return out


def _pairs(s1: cq.Shape, s2: cq.Shape, reach: float):
    for a in _near(s1, s2, reach):
        for b in _near(s2, a, reach):
            yield a, b


def _exact(s1: cq.Shape, s2: cq.Shape) -> float:
    best = np.inf
    for a, b in _pairs(s1, s2, 1.0):
        try:
            best = min(best, geom.distance(a, b))
        except RuntimeError as exc:
            raise AssemblyCheckError(str(exc)) from None
    return best if np.isfinite(best) else 1.0   # nothing within 1 mm: at least that far


def _overlap(s1: cq.Shape, s2: cq.Shape) -> float:
    return sum(a.intersect(b).Volume() for a, b in _pairs(s1, s2, 0.0))


class _Checker:
    def __init__(self, world: _World, sequence: Sequence):
        self.w, self.seq = world, sequence
        self.exact_cache: dict = {}
        self.boards = {name for name, p in world.placed.items() if p.part.kind == "board"}

    # -- distances ------------------------------------------------------------------------------------------
    def _lower_bound(self, moving: str, offset, other: str) -> float:
        """A lower bound of the distance between `moving` at `offset` and `other` (in place)."""
        box = (self.w.boxes[moving][0] + offset, self.w.boxes[moving][1] + offset)
        gap = _box_gap(box, self.w.boxes[other])
        if gap > 3.0:
            return gap
        return geom.mesh_distance(self.w.obj(moving, offset), self.w.obj(other)) - 2 * MESH_DEFLECTION

    def _exact_at(self, moving: str, offset, other: str) -> tuple[float, float]:
        """(exact distance, common volume when touching). A KiCad board (hundreds of component models) is measured
        on its mesh only: OpenCASCADE's distance and booleans on it take minutes and gigabytes. The faces a board
        meets (its PCB's, a standoff's ends) are planar, which a mesh holds exactly; no common volume is measured."""
        key = (moving, other, tuple(np.round(offset, 4)))
        if key in self.exact_cache:
            return self.exact_cache[key]
        if moving in self.boards or other in self.boards:
            d = geom.mesh_distance(self.w.obj(moving, offset), self.w.obj(other))
            self.exact_cache[key] = (max(d, 0.0), 0.0)
        else:
            a, b = self.w.shape(moving, offset), self.w.shape(other)
            d = _exact(a, b)
            self.exact_cache[key] = (d, _overlap(a, b) if d < TOUCH else 0.0)
        return self.exact_cache[key]

    # -- one step -------------------------------------------------------------------------------------------
    def sweep(self, step: Step, placed: list[str], result: StepResult) -> None:
        moving = step.parts
        fits = set(step.fits)
        others = [n for n in placed if n not in fits]
        fitted = [n for n in placed if n in fits]
        if placed:
            start = self.w.bbox(moving, step.path[0])
            if _box_gap(start, self.w.bbox(placed)) <= 0:
                result.problems.append(Problem(step.label, f"its start {step.path[0].tolist()} is not outside what is "
                                               f"already assembled (bounding boxes overlap): start further out"))
                return
        closest, closest_to = np.inf, ""
        segments = list(zip(step.path[:-1], step.path[1:]))
        for k, (p0, p1) in enumerate(segments):
            length = float(np.linalg.norm(p1 - p0))
            result.path_length += length
            u = (p1 - p0) / length
            t, next_fit = 0.0, 0.0
            while True:
                offset = p0 + u * t
                final = k == len(segments) - 1 and t >= length
                result.samples += 1
                d_min = np.inf
                for m in moving:
                    for o in others:
                        d = self._lower_bound(m, offset, o)
                        if d < MIN_STEP:
                            d, overlap = self._exact_at(m, offset, o)
                            if d < TOUCH:
                                if overlap > VOLUME_TOLERANCE:
                                    result.problems.append(Problem(step.label, (
                                        f"{m} collides with {o} {_where(result.path_length - length + t, final)} "
                                        f"(common volume {overlap:.1f} mm^3)")))
                                    return
                                if not final:
                                    result.problems.append(Problem(step.label, (
                                        f"{m} touches {o} {_where(result.path_length - length + t, final)}: "
                                        f"declare it a fit or guide of the step, or change the path")))
                                    return
                        if not final and d < closest:
                            closest, closest_to = d, f"{m} x {o}"
                        d_min = min(d_min, d)
                if fitted and (t >= next_fit or t >= length):
                    next_fit = t + FIT_STEP
                    for m in moving:
                        for o in fitted:
                            if self._lower_bound(m, offset, o) > 0:
                                continue
                            d, overlap = self._exact_at(m, offset, o)
                            if overlap > VOLUME_TOLERANCE:
                                result.problems.append(Problem(step.label, (
                                    f"{m} collides with {o} (a declared fit) {_where(result.path_length - length + t, final)} "
                                    f"(common volume {overlap:.1f} mm^3)")))
                                return
                if t >= length:
                    break
                advance = max(d_min, MIN_STEP)
                if fitted:
                    advance = min(advance, FIT_STEP)
                # Within one minimum step of a waypoint, go to it: a part seating on its neighbours is in place
                # there, not a hair short of it.
                t = length if t + advance > length - MIN_STEP else t + advance
        if np.isfinite(closest):
            result.closest, result.closest_to = round(float(closest), 3), closest_to

    def tight_rings(self, step: Step, placed: list[str], result: StepResult, params, seats: dict) -> None:
        """A step that is not a press must not put a bearing's tight ring onto its seat (see the module's text)."""
        moving, here = set(step.parts), set(placed)
        for name, seat in seats.items():
            tight = seat.journal if seat.inner_turns else seat.housing
            if (name in moving and tight in here) or (name in here and tight in moving):
                what = f"moving {name} onto it" if name in moving else f"moving {tight} into it"
                result.problems.append(Problem(step.label, (
                    f"{name}'s tight {seat.tight_ring} ring ({seat.tolerance(seat.tight_ring)} on {tight}) is pushed onto "
                    f"its seat by {what}: the force goes through the balls; press it with a tool on that ring")))
                return

    def press(self, step: Step, placed: list[str], result: StepResult, params=None, seats=None) -> None:
        bearing = step.parts[0]
        frame = self.w.frames[bearing]
        axis = frame[:3, 2]
        travel = -step.path[0] / np.linalg.norm(step.path[0])
        if abs(abs(float(axis @ travel)) - 1) > 1e-6:
            result.problems.append(Problem(step.label, f"{bearing} is not pressed along its axis"))
            return
        part = self.w.placed[bearing].part
        is_bearing = params is not None and params.root.node("purchased").has(part.design) \
            and params.purchased(part.design).text("kind") == "bearing"
        if is_bearing:
            seat = (seats or {}).get(bearing)
            if not step.press_ring:
                result.problems.append(Problem(step.label, f"{bearing}: say which ring the tool bears on "
                                                           f"(press: inner or press: outer)"))
                return
            if seat is not None:
                tight = seat.journal if seat.inner_turns else seat.housing
                if step.press_ring != seat.tight_ring:
                    result.problems.append(Problem(step.label, (
                        f"{bearing} is pressed by its {step.press_ring} ring, but its tight ring is the {seat.tight_ring} "
                        f"({seat.tolerance(seat.tight_ring)} on {tight}): the press force would go through the balls")))
                    return
                if tight not in placed:
                    result.problems.append(Problem(step.label, f"{bearing}: its tight {seat.tight_ring} ring's seat "
                                                               f"{tight} is not in place to press it onto"))
                    return
            if step.press_ring == "inner":
                self._sleeve(step, placed, result, params, bearing, frame, travel)
                return
        bb = self.w.boxes[bearing]
        centre = (bb[0] + bb[1]) / 2
        back = centre - travel * _half_extent(bb, travel)   # the bearing's trailing face
        diameter = _diameter_across(bb, travel) - 1.0
        self._tool(step, placed, result, f"press arbor for {bearing}", back, -travel, diameter, np.inf, diameter,
                   exclude={bearing})

    def _sleeve(self, step: Step, placed: list[str], result: StepResult, params, bearing: str, frame, travel) -> None:
        """A sleeve on the bearing's inner ring, over the journal, from the bearing's trailing face outwards until it
        leaves the assembly so far: it must not cut into anything in place (the journal runs inside its bore)."""
        item = params.purchased(self.w.placed[bearing].part.design)
        bore = item.num("bore") + 2 * SLEEVE_CLEARANCE
        outside = item.num("inner_ring_outside") - 2 * SLEEVE_CLEARANCE
        width = item.num("width")
        axis = frame[:3, 2]
        sign = 1.0 if float(axis @ travel) > 0 else -1.0        # the bearing moves towards sign * axis
        face_z = 0.0 if sign > 0 else width                       # its trailing face, in its own frame
        start = frame[:3, :3] @ np.array([0, 0, face_z]) + frame[:3, 3]
        names = [n for n in placed if n != bearing]
        if not names:
            result.tools.append({"tool": f"press sleeve for {bearing} on its inner ring", "reach_mm": 0.0,
                                 "clearance_mm": None})
            return
        reach = _exit_distance(start, -travel, self.w.bbox(names + [bearing])) + OUTSIDE_MARGIN
        z0, z1 = sorted((face_z, face_z - sign * reach))
        tube = cq.Solid.makeCylinder(outside / 2, z1 - z0, cq.Vector(0, 0, z0)).cut(
            cq.Solid.makeCylinder(bore / 2, z1 - z0 + 2, cq.Vector(0, 0, z0 - 1)))
        tube = tube.moved(location(frame))
        tb = tube.BoundingBox()
        box = (np.array([tb.xmin, tb.ymin, tb.zmin]), np.array([tb.xmax, tb.ymax, tb.zmax]))
        worst = np.inf
        for n in names:
            if _box_gap(box, self.w.boxes[n]) > 1.0:
                continue
            common = _overlap(tube, self.w.shape(n))
            if common > VOLUME_TOLERANCE:
                result.problems.append(Problem(step.label, (
                    f"press sleeve for {bearing} ({bore:g}/{outside:g} mm, on its inner ring): hits {n} "
                    f"(common volume {common:.1f} mm^3)")))
                return
            worst = min(worst, _exact(tube, self.w.shape(n)))
        result.tools.append({"tool": f"press sleeve for {bearing} on its inner ring", "reach_mm": round(reach, 1),
                             "clearance_mm": None if not np.isfinite(worst) else round(float(worst), 3)})

    def fasteners(self, step: Step, placed: list[str], result: StepResult, params) -> None:
        done = list(placed)
        for screw in step.fasteners:
            part = self.w.placed[screw].part
            item = params.purchased(part.design)
            frame = self.w.frames[screw]
            axis = frame[:3, 2]                     # shank along +z, head on -z
            # a set screw has no head: the driver starts at its socket end, as wide as its thread
            headless = item.text("kind") == "set_screw"
            head_top = frame[:3, 3] - axis * (0.0 if headless else item.num("head_height"))
            width = item.num("diameter" if headless else "head_diameter")
            driver = self.seq.driver_for(part.design, step.driver)
            self._tool(step, done, result, f"{screw} ({driver.name})", head_top, -axis, width,
                       driver.length, driver.handle, blade=driver.blade, exclude={screw})
            done.append(screw)

    def access(self, step: Step, placed: list[str], result: StepResult) -> None:
        name, along = step.access
        driver = self.seq.drivers[name]
        bb = self.w.bbox(step.parts)
        centre = (bb[0] + bb[1]) / 2
        start = centre + along * _half_extent(bb, along)
        # an external ring's pliers straddle the shaft the ring goes on: the tool is drawn solid, so that shaft is left out
        self._tool(step, placed, result, f"{'/'.join(step.parts)} ({driver.name})", start, along, driver.blade,
                   driver.length, driver.handle, exclude=set(step.parts) | set(step.straddles))

    def _tool(self, step: Step, placed: list[str], result: StepResult, label: str, start, direction, diameter: float,
              blade_length: float, handle: float, blade: float | None = None, exclude=frozenset()) -> None:
        """Cylinders along `direction` from `start`: `diameter` (the screw head, an arbor) and `blade` up to
        `blade_length`, then `handle`, each until the bounding box of everything so far is left."""
        names = [n for n in placed if n not in exclude]
        if not names:
            # nothing else in place yet (a bearing pressed onto the first part of a subassembly): clear by itself
            result.tools.append({"tool": label, "reach_mm": 0.0, "clearance_mm": None})
            return
        everything = self.w.bbox(names + list(exclude))
        reach = _exit_distance(start, direction, everything) + OUTSIDE_MARGIN
        pieces = [(diameter, 0.0, reach)]
        if blade is not None and blade > diameter:
            pieces.append((blade, 0.0, min(blade_length, reach)))
        if blade_length < reach:
            pieces.append((handle, blade_length, reach))
        worst = np.inf
        for dia, a, b in pieces:
            if b - a <= 0:
                continue
            rot = _rotation_to(direction)
            centre = start + direction * (a + b) / 2
            cyl = fcl.CollisionObject(fcl.Cylinder(dia / 2, b - a), fcl.Transform(rot, centre))
            solid = None
            for n in names:
                box = (self.w.boxes[n][0], self.w.boxes[n][1])
                lo = np.minimum(start + direction * a, start + direction * b) - dia / 2
                hi = np.maximum(start + direction * a, start + direction * b) + dia / 2
                if _box_gap((lo, hi), box) > 3.0:
                    continue
                d = geom.mesh_distance(cyl, self.w.obj(n)) - 2 * MESH_DEFLECTION
                if d < MIN_STEP and n in self.boards and d <= 0:
                    result.problems.append(Problem(step.label, f"{label}: the {dia:g} mm tool along the axis hits {n}"))
                    return
                if d < MIN_STEP and n not in self.boards:
                    if solid is None:
                        base = start + direction * a
                        solid = cq.Solid.makeCylinder(dia / 2, b - a, cq.Vector(*base), cq.Vector(*direction))
                    d = _exact(solid, self.w.shape(n))
                    if d < TOUCH and _overlap(solid, self.w.shape(n)) > VOLUME_TOLERANCE:
                        result.problems.append(Problem(step.label, (
                            f"{label}: the {dia:g} mm {'handle' if a > 0 else 'tool'} along the axis hits {n} "
                            f"{a:.0f}..{b:.0f} mm out from the head")))
                        return
                worst = min(worst, d)
        result.tools.append({"tool": label, "reach_mm": round(reach, 1),
                             "clearance_mm": None if not np.isfinite(worst) else round(float(worst), 3)})


def _where(distance: float, final: bool) -> str:
    return "in its final place" if final else f"{distance:.1f} mm along its path"


def _half_extent(bb, direction) -> float:
    return float(np.abs(direction) @ ((bb[1] - bb[0]) / 2))


def _diameter_across(bb, axis) -> float:
    size = bb[1] - bb[0]
    return float(max(s for s, a in zip(size, np.abs(axis)) if a < 0.5))


def _exit_distance(start, direction, box) -> float:
    """How far from `start` along `direction` the ray leaves the box (0 when it starts outside and moves away)."""
    far = 0.0
    for i in range(3):
        if abs(direction[i]) < 1e-12:
            continue
        edge = box[1][i] if direction[i] > 0 else box[0][i]
        far = max(far, (edge - start[i]) / direction[i])
    return far


def _rotation_to(direction) -> np.ndarray:
    """A rotation taking +z to `direction` (FCL's cylinders lie along z)."""
    z = np.asarray(direction, dtype=float) / np.linalg.norm(direction)
    helper = np.array([1.0, 0, 0]) if abs(z[0]) < 0.9 else np.array([0, 1.0, 0])
    x = np.cross(helper, z)
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    return np.column_stack([x, y, z])


def check(params, assembly: Assembly, sequence: Sequence, progress=None) -> Report:
    began, began_cpu = time.monotonic(), time.process_time()
    world = _World(assembly)
    checker = _Checker(world, sequence)
    seats = fits_mod.seats(params, assembly.parts)
    results = []
    steps = sequence.steps()
    placed: dict[str, list[str]] = {}
    for i, step in enumerate(steps):
        if progress:
            progress(i, len(steps), step.label)
        here = placed.setdefault(step.context, [])
        result = StepResult(step.label, step.context, list(step.parts) + list(step.fasteners), step.name,
                            step.picture(i + 1))
        if step.fixture:
            result.note = "held (the first part of its context)"
        elif step.flexible:
            result.note = f"placed by hand, not swept: {step.flexible}"
            if step.access:
                checker.access(step, here, result)
        elif step.parts:
            checker.sweep(step, here, result)
            if step.press and not result.problems:
                checker.press(step, here, result, params, seats)
            elif not step.press and not result.problems:
                checker.tight_rings(step, here, result, params, seats)
        else:
            result.note = "screws only: each one's driver checked along its axis"
        here.extend(step.parts)
        if step.fasteners and not result.problems:
            checker.fasteners(step, here, result, params)
        here.extend(step.fasteners)
        results.append(result)
    return Report(results, time.monotonic() - began, time.process_time() - began_cpu)


def format_report(report: Report) -> str:
    lines = [f"assembly sequence check: {len(report.steps)} steps in {report.seconds:.0f} s "
             f"({report.cpu_seconds:.0f} s of CPU), {len(report.problems)} problems"]
    for s in report.steps:
        flag = "  FAIL" if s.problems else ""
        detail = s.note or (f"path {s.path_length:.0f} mm in {s.samples} samples"
                            + (f", closest {s.closest:.2f} mm ({s.closest_to})" if s.closest is not None else ""))
        lines.append(f"{s.label}: {detail}{flag}")
        for t in s.tools:
            lines.append(f"    tool {t['tool']}: clear to {t['reach_mm']} mm out"
                         + (f", closest {t['clearance_mm']:.2f} mm" if t["clearance_mm"] is not None else ""))
        for p in s.problems:
            lines.append(f"    PROBLEM {p.what}")
    return "\n".join(lines)


def report_json(report: Report) -> dict:
    return {"ok": report.ok, "seconds": round(report.seconds, 1), "cpu_seconds": round(report.cpu_seconds, 1),
            "problems": [str(p) for p in report.problems],
            "steps": [{"step": s.label, "context": s.context, "name": s.name, "picture": s.picture, "parts": s.parts, "path_mm": round(s.path_length, 1),
                       "samples": s.samples, "closest_mm": s.closest, "closest_pair": s.closest_to, "note": s.note,
                       "tools": s.tools, "problems": [p.what for p in s.problems]} for s in report.steps]}
