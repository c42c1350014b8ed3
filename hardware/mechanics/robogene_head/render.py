# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""PNG renders of the assembly with VTK's offscreen (EGL) window: no X display needed."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import vtk

from . import kinematics
from .assembly import Assembly

# (name, control-board pose, camera azimuth, elevation)
VIEWS = [
    ("head-front-3q", {}, 35, 15),
    ("head-look-left-up", {"neck_pitch": 15, "neck_yaw": 35, "eyes_tilt": 10, "eyes_version": 15}, 30, 12),
    ("head-nod-roll-converge", {"neck_pitch": -20, "neck_roll": 15, "eyes_tilt": -15, "eyes_vergence": 40}, -40, 20),
    ("head-side", {}, 90, 0),
]


def _actor(shape, color):
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
    return actor


def _face_plate_actor(stl: Path, head_pose: np.ndarray, params) -> vtk.vtkActor:
    """The OpenSCAD face plate (modelled flat, x across the head, y up) on the side plates' front edges."""
    reader = vtk.vtkSTLReader()
    reader.SetFileName(str(stl))
    x_front = params.geometry("head", "side_plate").num("x_max")
    m = np.array([[0, 0, 1, x_front], [1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 1]], dtype=float)
    m = head_pose @ m
    matrix = vtk.vtkMatrix4x4()
    for i in range(4):
        for j in range(4):
            matrix.SetElement(i, j, m[i, j])
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.SetUserMatrix(matrix)
    actor.GetProperty().SetColor(0.93, 0.93, 0.9)
    actor.GetProperty().SetOpacity(0.55)
    return actor


def render(assembly: Assembly, control: dict, azimuth: float, elevation: float, path: Path, size=(800, 640),
           face_plate: Path | None = None) -> None:
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    window.SetMultiSamples(4)
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(0.97, 0.97, 0.98)
    renderer.SetBackground2(0.82, 0.86, 0.92)
    renderer.GradientBackgroundOn()
    window.AddRenderer(renderer)
    for placed in assembly.pose(control):
        if placed.part.kind == "reserved":
            continue
        renderer.AddActor(_actor(placed.shape, placed.part.color))
    if face_plate is not None:
        head_pose = kinematics.link_poses(assembly.params, kinematics.chain_angles(assembly.params, control))["head_frame"]
        renderer.AddActor(_face_plate_actor(face_plate, head_pose, assembly.params))
    camera = renderer.GetActiveCamera()
    # World z is up; look at the head from the front (+x), turned by azimuth about z and raised by elevation.
    camera.SetFocalPoint(0, 0, 90)
    az, el = np.radians(azimuth), np.radians(elevation)
    camera.SetPosition(600 * np.cos(el) * np.cos(az), 600 * np.cos(el) * np.sin(az), 90 + 600 * np.sin(el))
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera()
    camera.Zoom(1.25)
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
