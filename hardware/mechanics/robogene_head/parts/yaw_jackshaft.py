# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The neck yaw's drive up to its motor pulley: the 22/7 gearhead clamped by its body in a machined housing on the
head floor's top face, a clamp coupling from its 4 mm shaft to a 6 mm jackshaft in two bearings of the housing,
pointing down through the floor, and the catalogue 14T XL pulley on the jackshaft under it
(geometry.yaw_jackshaft; the stage itself is parts/jackshaft.py).

Why: the gearhead's 10 mm shaft leaves too little below the floor for a catalogue pulley, and the MXL belt the
old bonded motor pulley ran could not carry the drive's torque (docs/fabricate.md, "Torque paths"). The stage frame
in the head frame: its axis (+y) points down at geometry.yaw_jackshaft.axis, u (ahead) from the axis towards the yaw
axis along the belt, v across it; the plate is the floor, from its top face (inner) to its underside (outer)."""
from __future__ import annotations

import math

import cadquery as cq

from robogene_head_model import drive_limits
from robogene_head_model.params import HeadParameters, ParameterError

from . import jackshaft
from .base import Part, loc

JOINT = "neck_yaw"
KEY = "yaw_jackshaft"


def axis(params: HeadParameters) -> tuple[float, float]:
    """The jackshaft's axis (x, y) in the head frame."""
    n = params.geometry(KEY)
    x, y = n.vec("axis", 2)
    if math.hypot(x, y) == 0:
        raise n.fail("axis", "lies on the yaw axis: the belt needs the two apart")
    return x, y


def centre_distance(params: HeadParameters) -> float:
    """The belt's centre distance as drawn: from the yaw axis to the jackshaft's."""
    return drive_limits.belt_centre(params, JOINT)


def stage(params: HeadParameters) -> jackshaft.Stage:
    x, y = axis(params)
    floor = params.geometry("head", "floor")
    if not (floor.num("x_min") < x < floor.num("x_max") and abs(y) < floor.num("half_width")):
        raise ParameterError(f"{params.path}: geometry.{KEY}.axis: ({x:g}, {y:g}) is not on the head floor")
    # u towards the yaw axis; the stage's +y (its axis, gearhead to pulley) down through the floor
    turn = math.degrees(math.atan2(-y, -x))
    return jackshaft.Stage(JOINT, KEY, "head_frame", 0.0, 0.0, inner=0.0,
                           outer=floor.num("thickness", positive=True), plate="head floor",
                           placement=loc(x, y, 0, rz=turn) * loc(rx=-90))


def layout(params: HeadParameters) -> jackshaft.Layout:
    return jackshaft.layout(params, stage(params))


def build(params: HeadParameters) -> list[Part]:
    """The housing, jackshaft, bearings, coupling, motor pulley, the yaw drive and their screws (head frame)."""
    return jackshaft.build(params, stage(params))


def floor_tools(params: HeadParameters) -> list[cq.Shape]:
    """What the head floor needs for the stage (head frame): the jackshaft's passage and the housing's fixings,
    slots `slot` long along the belt, so the housing slides to tension it."""
    return jackshaft.plate_tools(params, stage(params))
