# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The eye tilt's drive up to its motor pulley: the 16/7 gearhead clamped by its body in a machined housing on the
left side plate's inner face, a clamp coupling from its 3 mm shaft to a 6 mm jackshaft in two bearings of the
housing, and the catalogue 14T XL pulley on the jackshaft outside the plate (geometry.tilt_jackshaft; the stage
itself is parts/jackshaft.py).

Why: the gearhead's 8 mm shaft leaves too little beyond any plate its flange is screwed to for a catalogue
pulley or coupling hub (docs/fabricate.md, "Torque paths"). The stage frame is the head frame: the axis along +y
(outwards through the left side plate), u ahead (+x), v above (+z)."""
from __future__ import annotations

import cadquery as cq

from robogene_head_model.params import HeadParameters

from . import jackshaft, mounts
from .base import Part

JOINT = "eyes_tilt"


def stage(params: HeadParameters) -> jackshaft.Stage:
    head = params.geometry("head")
    hw = head.node("floor").num("half_width", positive=True)
    tm = head.node("tilt_motor")
    return jackshaft.Stage(JOINT, "tilt_jackshaft", "head_frame", tm.num("x"), tm.num("z"),
                           inner=hw - head.node("side_plate").num("thickness", positive=True), outer=hw,
                           plate="side plate")


def layout(params: HeadParameters) -> jackshaft.Layout:
    return jackshaft.layout(params, stage(params))


def build(params: HeadParameters) -> list[Part]:
    """The housing, jackshaft, bearings, coupling, motor pulley, the tilt drive and their screws (head frame)."""
    return jackshaft.build(params, stage(params))


def side_plate_tools(params: HeadParameters) -> list[cq.Shape]:
    """What the left side plate needs for the stage: the jackshaft's passage and the housing's fixings, slots
    `slot` long along x (the belt's line is within 11 deg of x) so the housing slides to tension the belt."""
    return jackshaft.plate_tools(params, stage(params))
