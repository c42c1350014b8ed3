# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""PNG renders of the assembly with VTK's offscreen (EGL) window: no X display needed."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import vtk

from .assembly import Assembly


@dataclass(frozen=True)
class View:
    name: str
    pose: dict                 # control-board angles (deg)
    azimuth: float             # camera direction about z from the front (+x), deg
    elevation: float
    hidden: tuple = ()         # parts left out, to show what they cover
    links: tuple = ()          # only the parts on these links (default: all)


VIEWS = [
    View("head-front-3q", {}, 35, 15),
    View("head-look-left-up", {"neck_pitch": 15, "neck_yaw": 35, "eyes_tilt": 10, "eyes_version": 15}, 30, 12),
    View("head-nod-roll-converge", {"neck_pitch": -20, "neck_roll": 15, "eyes_tilt": -15, "eyes_vergence": 40}, -40, 20),
    View("head-side", {}, 90, 0),
    # The board bay with the skirt off: the three motor-control boards from KiCad between plate and flange.
    View("board-bay", {}, 150, 15, hidden=("neck_base_skirt",), links=("neck_base",)),
]


def _actor(shape, color, alpha=1.0):
    poly = shape.toVtkPolyData(0.1, 0.3)
    normals = vtk.vtkPolyDataNormals()
    normals.SetInputData(poly)
    normals.SetFeatureAngle(40)
    normals.SplittingOn()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetColor(*color)
    prop.SetSpecular(0.3)
    prop.SetSpecularPower(20)
    prop.SetAmbient(0.15)
    prop.SetOpacity(alpha)
    return actor


BACKGROUND = ((0.97, 0.97, 0.98), (0.82, 0.86, 0.92))    # the package's pictures' gradient, bottom to top


def stage(size, background=BACKGROUND):
    """An off-screen window of size (px) with one renderer on a gradient background (bottom, top colours)."""
    bottom, top = background
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    window.SetMultiSamples(4)
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(*bottom)
    renderer.SetBackground2(*top)
    renderer.GradientBackgroundOn()
    window.AddRenderer(renderer)
    return window, renderer


def shoot(window, renderer, focus: np.ndarray, distance: float, azimuth: float, elevation: float, zoom: float,
          path: Path) -> None:
    """Aim the camera at focus from distance (mm), turned by azimuth (deg) about world z and raised by elevation,
    fit the scene, zoom, and write the window as a PNG."""
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(*focus)
    az, el = np.radians(azimuth), np.radians(elevation)
    camera.SetPosition(*(focus + distance * np.array([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)])))
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera()
    camera.Zoom(zoom)
    renderer.ResetCameraClippingRange()
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    path.parent.mkdir(parents=True, exist_ok=True)
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(str(path))
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    window.Finalize()


def render(assembly: Assembly, view: View, path: Path, size=(800, 640)) -> None:
    window, renderer = stage(size)
    unknown = set(view.hidden) - {p.name for p in assembly.parts}
    if unknown:
        raise ValueError(f"view {view.name}: no part named {', '.join(sorted(unknown))}")
    for placed in assembly.pose(view.pose):
        if placed.part.name not in view.hidden and (not view.links or placed.part.link in view.links):
            for _, shape, color in placed.part.pieces(placed.shape):
                renderer.AddActor(_actor(shape, color, placed.part.alpha))
    # World z is up; look at the head from the front (+x), turned by azimuth about z and raised by elevation.
    shoot(window, renderer, np.array([0.0, 0.0, 90.0]), 600, view.azimuth, view.elevation, 1.25, path)
