# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Step-by-step assembly pictures from the assembly sequence: per step, what is already in place in grey, the
parts the step adds highlighted, its screws in blue, and the path the parts travel as an arrow. Also writes
the instructions page (assembly/steps/README.md) that lists the steps with their pictures."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import vtk

from .assembly import Assembly
from .render import shoot, stage
from .sequence import Sequence, Step

GREY = (0.78, 0.79, 0.81)
NEW = (0.95, 0.45, 0.1)
SCREWS = (0.15, 0.35, 0.85)
ARROW = (0.85, 0.1, 0.1)
SIZE = (720, 540)
STEP_BACKGROUND = ((1, 1, 1), (0.86, 0.89, 0.94))    # lighter than the views: the step's new part stands out


class _Meshes:
    def __init__(self, assembly: Assembly):
        self.placed = {p.part.name: p for p in assembly.pose({})}
        self.polys: dict[str, vtk.vtkPolyData] = {}

    def poly(self, name: str) -> vtk.vtkPolyData:
        if name not in self.polys:
            raw = self.placed[name].shape.toVtkPolyData(0.15, 0.4)
            normals = vtk.vtkPolyDataNormals()
            normals.SetInputData(raw)
            normals.SetFeatureAngle(40)
            normals.SplittingOn()
            normals.Update()
            self.polys[name] = normals.GetOutput()
        return self.polys[name]

    def bbox(self, names):
        boxes = [self.placed[n].shape.BoundingBox() for n in names]
        return (np.array([min(b.xmin for b in boxes), min(b.ymin for b in boxes), min(b.zmin for b in boxes)]),
                np.array([max(b.xmax for b in boxes), max(b.ymax for b in boxes), max(b.zmax for b in boxes)]))


def _actor(poly, color, opacity=1.0, offset=(0, 0, 0)):
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(poly)
    mapper.ScalarVisibilityOff()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.SetPosition(*offset)
    prop = actor.GetProperty()
    prop.SetColor(*color)
    prop.SetOpacity(opacity)
    prop.SetSpecular(0.25)
    prop.SetAmbient(0.2)
    return actor


def _arrow(points: list[np.ndarray], radius: float):
    """A polyline with a cone on its last segment, pointing along the travel."""
    actors = []
    for a, b in zip(points[:-1], points[1:]):
        if np.linalg.norm(b - a) < 1e-6:
            continue
        line = vtk.vtkLineSource()
        line.SetPoint1(*a)
        line.SetPoint2(*b)
        tube = vtk.vtkTubeFilter()
        tube.SetInputConnection(line.GetOutputPort())
        tube.SetRadius(radius)
        tube.SetNumberOfSides(12)
        tube.Update()
        actors.append(_actor(tube.GetOutput(), ARROW))
    a, b = points[-2], points[-1]
    direction = (b - a) / max(np.linalg.norm(b - a), 1e-9)
    cone = vtk.vtkConeSource()
    cone.SetHeight(radius * 8)
    cone.SetRadius(radius * 3)
    cone.SetResolution(16)
    cone.SetDirection(*direction)
    cone.SetCenter(*(b - direction * radius * 4))
    cone.Update()
    actors.append(_actor(cone.GetOutput(), ARROW))
    return actors


def render_step(meshes: _Meshes, step: Step, placed: list[str], path: Path) -> None:
    window, renderer = stage(SIZE, STEP_BACKGROUND)
    for name in placed:
        renderer.AddActor(_actor(meshes.poly(name), GREY, 0.55 if placed and step.parts else 1.0))
    for name in step.parts:
        renderer.AddActor(_actor(meshes.poly(name), NEW))
    for name in step.fasteners:
        renderer.AddActor(_actor(meshes.poly(name), SCREWS))
    shown = placed + step.parts + step.fasteners
    lo, hi = meshes.bbox(shown)
    if step.parts and len(step.path) > 1:
        mlo, mhi = meshes.bbox(step.parts)
        centre = (mlo + mhi) / 2
        points = [centre + p for p in step.path]
        radius = max(0.6, 0.006 * float(np.linalg.norm(hi - lo)))
        for actor in _arrow(points, radius):
            renderer.AddActor(actor)
        # the parts where they start, faint, so the arrow reads as their travel
        for name in step.parts:
            renderer.AddActor(_actor(meshes.poly(name), NEW, 0.18, offset=step.path[0]))
    shoot(window, renderer, (lo + hi) / 2, 800, 35, 22, 1.15, path)


def render_all(assembly: Assembly, sequence: Sequence, folder: Path, progress=None) -> list[Path]:
    meshes = _Meshes(assembly)
    placed: dict[str, list[str]] = {}
    out = []
    steps = sequence.steps()
    for i, step in enumerate(steps):
        if progress:
            progress(i, len(steps), step.label)
        here = placed.setdefault(step.context, [])
        target = folder / step.picture(i + 1)
        render_step(meshes, step, list(here), target)
        out.append(target)
        here.extend(step.parts + step.fasteners)
    return out


def instructions(sequence: Sequence, report: dict) -> str:
    """The package's assembly page: every step with its picture, path, fits, screws and what the check found."""
    by_label = {s["step"]: s for s in report["steps"]}
    lines = ["# Assembling the Robogene head, step by step", "",
             "Generated by `make fab` from hardware/mechanics/assembly-sequence.yaml; every step below was checked "
             "(reports/assembly.txt): the parts travel along the arrow from outside to their place without touching "
             "anything but the fits named, and every screw's driver reaches it. Grey: already in place; orange: this "
             "step's parts; blue: its screws. Subassemblies are built on the bench first and go in whole.", ""]
    current = None
    for i, step in enumerate(sequence.steps()):
        if step.context != current:
            current = step.context
            lines += ["", f"## {'Final assembly' if current == 'main' else 'Subassembly: ' + current}", ""]
        lines.append(f"### {i + 1}. {step.name}")
        lines.append("")
        lines.append(f"![{step.label}]({step.picture(i + 1)})")
        lines.append("")
        what = f"subassembly `{step.subassembly}`" if step.subassembly else ", ".join(f"`{p}`" for p in step.parts)
        if step.fixture:
            lines.append(f"- Start with {what}.")
        elif step.flexible:
            lines.append(f"- Place {what} by hand: {step.flexible}.")
        elif step.parts:
            moves = " then ".join(f"{np.round(-p, 1).tolist()}" for p in step.path[:-1])
            lines.append(f"- Move {what} from its start in the direction {moves} mm to its place.")
        if step.fits:
            lines.append(f"- It slides on or in: {', '.join(f'`{f}`' for f in step.fits)}.")
        if step.press:
            lines.append("- Press it in with an arbor on the outer ring.")
        if step.fasteners:
            lines.append(f"- Screws: {', '.join(f'`{f}`' for f in step.fasteners)}"
                         + (f" (driver {step.driver})" if step.driver else "") + ".")
        if step.why:
            lines.append(f"- Why: {step.why}.")
        checked = by_label.get(step.label)
        if checked and checked.get("closest_mm") is not None:
            lines.append(f"- Checked: closest {checked['closest_mm']:.2f} mm on the way ({checked['closest_pair']}).")
        lines.append("")
    return "\n".join(lines) + "\n"
