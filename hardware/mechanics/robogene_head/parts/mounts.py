# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Motor mounts and timing pulleys: small machined parts shared by several joints."""
from __future__ import annotations

import math

import cadquery as cq

from .. import geom
from ..params import HeadParameters
from . import gearhead_screws

FIXING_CLEARANCE = 3.4   # M3, ISO 273 medium
FIXING_SCREW = "iso7380-M3x8"


def mount_plate(outline: tuple[float, float, float, float], thickness: float, hole: float, gearhead_diameter: float,
                fixings: tuple[tuple[float, float], ...] = (), slot: float = 0.0, counterbores: bool = True) -> cq.Shape:
    """Flange plate in z 0..thickness with its axis at the origin, outline (x0, x1, y0, y1); the gearhead's flange
    bears on z = thickness. A pilot hole for the output shaft, the gearhead's four M2 screw holes (counterbored
    from z = 0 unless counterbores is False: gearhead_screws), and M3 clearance holes at `fixings` for the screws
    that hold the plate on the structure, drawn as slots `slot` long along x where the plate must slide."""
    x0, x1, y0, y1 = outline
    plate = geom.box(x0, x1, y0, y1, 0, thickness)
    holes = [geom.cyl("z", hole, -1, thickness + 1), *gearhead_screws.holes(gearhead_diameter, thickness, counterbores)]
    for x, y in fixings:
        holes.append(geom.cyl("z", FIXING_CLEARANCE, -1, thickness + 1, (x - slot / 2, y)))
        if slot > 0:
            holes.append(geom.cyl("z", FIXING_CLEARANCE, -1, thickness + 1, (x + slot / 2, y)))
            holes.append(geom.box(x - slot / 2, x + slot / 2, y - FIXING_CLEARANCE / 2, y + FIXING_CLEARANCE / 2,
                                  -1, thickness + 1))
    return geom.single_solid(geom.cut(plate, *holes), "mount_plate")


def pitch_diameter(params: HeadParameters, teeth: int) -> float:
    return teeth * params.geometry("pulleys").num("pitch_mxl", positive=True) / math.pi


def pulley(params: HeadParameters, teeth: int, bore: float) -> cq.Shape:
    """MXL pulley envelope, z 0..width: toothed body at its outside diameter between two flanges."""
    width = params.geometry("pulleys").num("width", positive=True)
    outside = pitch_diameter(params, teeth) - 0.508  # MXL pitch-line differential
    flange = outside + 3.0
    body = geom.union(geom.cyl("z", flange, 0, 0.8), geom.cyl("z", outside, 0.8, width - 0.8),
                      geom.cyl("z", flange, width - 0.8, width))
    return geom.single_solid(geom.cut(body, geom.cyl("z", bore, -1, width + 1)), f"pulley_{teeth}T")


def belt_teeth(params: HeadParameters, centre_distance: float, teeth_a: int, teeth_b: int) -> int:
    """Closed MXL belt for two pulleys: pitch length 2C + pi(D+d)/2 + (D-d)^2/4C, rounded up to whole teeth
    (the motor is slotted to take up the difference)."""
    big, small = pitch_diameter(params, max(teeth_a, teeth_b)), pitch_diameter(params, min(teeth_a, teeth_b))
    length = 2 * centre_distance + math.pi * (big + small) / 2 + (big - small) ** 2 / (4 * centre_distance)
    return math.ceil(length / params.geometry("pulleys").num("pitch_mxl") - 1e-9)


def belts(params: HeadParameters) -> list[tuple[str, str, int]]:
    """(catalog key, joint, teeth) of the two timing belts; they have no solid in the assembly."""
    head = params.geometry("head")
    tilt = params.joints["eyes_tilt"].origin
    tm = head.node("tilt_motor")
    pulleys = params.geometry("pulleys")
    out = []
    for joint, distance, node in (
            ("neck_yaw", abs(head.num("yaw_motor_x")), pulleys.node("yaw")),
            ("eyes_tilt", math.hypot(tilt[0] - tm.num("x"), tilt[2] - tm.num("z")), pulleys.node("tilt"))):
        teeth = belt_teeth(params, distance, int(node.num("motor_teeth")), int(node.num("joint_teeth")))
        out.append((f"mxl-belt-{teeth}T", joint, teeth))
    return out


def pulley_note(params: HeadParameters, teeth: int, bore: float) -> str:
    """What the drawing of a pulley must say: its teeth are not modelled."""
    return (f"MXL pulley, {teeth} teeth, pitch dia. {pitch_diameter(params, teeth):.2f}, bore {bore:g} H7; "
            f"teeth not drawn: MXL profile")
