# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Pictures of the free spans as the build models them, at rest, among the parts they pass: what a lab lays the
cables to. Each flat cable is a ribbon of its width turned with the curve's carried frame, the round wires of a span
one tube of the bundle's diameter; the clamps are dots."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import vtk

from robogene_head_model.params import HeadParameters

from .. import geom, kinematics, render
from . import spans
from .clearance import bundle_od
from .plan import Harness, frame


@dataclass(frozen=True)
class Picture:
    name: str
    links: tuple[str, ...]        # the parts on these links are drawn
    hidden: tuple[str, ...]       # but those whose names start with one of these, which would hide the cables
    azimuth: float                # deg about world z from the front (+x)
    elevation: float
    zoom: float


PICTURES = [
    # Behind the eyes, from above and behind the head's left: the camera cables' loops about the pan axes and the
    # tilt axis, on the tilt frame's cable shelf, and the pan drives' loops across tilt.
    Picture("harness-eyes", ("head_frame", "eyes_tilt_link", "left_eye", "right_eye"),
            ("head_side_plate_left", "head_back_plate", "head_top_bar", "head_back_cover", "face_plate", "back_",
             "top_side_screw", "side_floor_screw_left", "eyes_tilt_j", "eyes_tilt_c", "tilt_housing_screw",
             "eyes_tilt_gearhead", "eyes_tilt_motor", "eyes_tilt_encoder", "eyes_tilt_belt"), 150, 40, 1.9),
]
CABLE, FLAT, CLAMP = (0.85, 0.15, 0.1), (0.2, 0.45, 0.95), (0.1, 0.1, 0.1)


def _polyline(points: np.ndarray, normals: np.ndarray | None = None) -> vtk.vtkPolyData:
    poly, pts, line = vtk.vtkPolyData(), vtk.vtkPoints(), vtk.vtkCellArray()
    line.InsertNextCell(len(points))
    for i, p in enumerate(points):
        pts.InsertNextPoint(*p)
        line.InsertCellPoint(i)
    poly.SetPoints(pts)
    poly.SetLines(line)
    if normals is not None:
        arr = vtk.vtkDoubleArray()
        arr.SetNumberOfComponents(3)
        for n in normals:
            arr.InsertNextTuple3(*n)
        poly.GetPointData().SetNormals(arr)
    return poly


def _actor(source, color) -> vtk.vtkActor:
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    return actor


def _span_actors(c: spans.Curve, od: float, flats: list[tuple[float, float]]) -> list[vtk.vtkActor]:
    out = []
    if od:
        tube = vtk.vtkTubeFilter()
        tube.SetInputData(_polyline(c.points))
        tube.SetRadius(od / 2)
        tube.SetNumberOfSides(16)
        out.append(_actor(tube, CABLE))
    for width, _ in flats:
        # the ribbon's normal at each node: the carried face normal (a node's first piece's; the last piece's at B)
        normals = np.vstack([c.normals, c.normals[-1:]])
        ribbon = vtk.vtkRibbonFilter()
        ribbon.SetInputData(_polyline(c.points, normals))
        ribbon.UseDefaultNormalOff()
        ribbon.SetWidth(width / 2)   # VTK lays the ribbon across the line and the normal: along the width
        out.append(_actor(ribbon, FLAT))
    return out


def draw(params: HeadParameters, harness: Harness, parts, picture: Picture, path: Path, size=(800, 640)) -> None:
    rest = kinematics.link_poses(params, {})
    window, renderer = render.stage(size)
    for p in parts:
        if p.link in picture.links and not p.name.startswith(picture.hidden) and p.kind != "board":
            for _, shape, color in p.pieces(p.shape.moved(geom.location(rest[p.link]))):
                renderer.AddActor(render._actor(shape, color, p.alpha))
    centre = []
    for (x, y), span in harness.spans.items():
        a, b = harness.spec.clamps[x], harness.spec.clamps[y]
        if a.link not in picture.links or b.link not in picture.links:
            continue
        fa, fb = frame(rest[a.link], a), frame(rest[b.link], b)
        c = spans.curve(fa, fb, span.length)
        flats = [(cls.width, cls.thickness) for _, cls, _ in span.members if cls.shape == "flat"]
        for actor in _span_actors(c, bundle_od(span), flats):
            renderer.AddActor(actor)
        for f in (fa, fb):
            dot = vtk.vtkSphereSource()
            dot.SetCenter(*f.at)
            dot.SetRadius(1.5)
            renderer.AddActor(_actor(dot, CLAMP))
        centre.append(c.points.mean(axis=0))
    focus = np.mean(centre, axis=0) if centre else np.array([0.0, 0.0, 150.0])
    render.shoot(window, renderer, focus, 600, picture.azimuth, picture.elevation, picture.zoom, path)
