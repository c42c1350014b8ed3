# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Neck base (plates, uprights, board bay), pitch stage and roll stage, with their drives."""
from __future__ import annotations

from .. import geom
from ..params import HeadParameters, ParameterError
from . import board_stack, gearhead_screws, mounts, purchased
from .base import ALUMINIUM, Part, loc

SCREW = "iso7380-M3x12"
STANDOFF = "standoff-M3x46-FF"
UPRIGHT_NOTE = ("M3 tapped (tap drill 2.5), drawn at 3.0: 2 x 6 deep in the bottom face, 4 x 8 deep in the outer face "
                "for the pitch motor mount (unused on the right upright)")
PITCH_STAGE_NOTE = "Rear lug: 2 x M3 tapped through (tap drill 2.5), drawn at 3.0, for the roll motor mount"


def _base(params: HeadParameters) -> list[Part]:
    g = params.geometry("neck_base")
    pl, fl, up = g.node("plate"), g.node("flange"), g.node("upright")
    L, W, T = pl.num("length", positive=True), pl.num("width", positive=True), pl.num("thickness", positive=True)
    bay, inset = g.num("bay_height", positive=True), g.num("corner_inset", positive=True)
    ft = fl.num("thickness", positive=True)
    ut, ul, gap = up.num("thickness", positive=True), up.num("length", positive=True), up.num("gap", positive=True)
    hp = params.joints["neck_pitch"].origin[2]
    corners = [(sx * (L / 2 - inset), sy * (W / 2 - inset)) for sx in (-1, 1) for sy in (-1, 1)]
    m3 = mounts.clearance_hole(params, SCREW)
    cable = g.node("cable_pass")
    c0, c1 = cable.vec("from_edge", 2)
    if not 0 <= c0 < c1 <= L:
        raise ParameterError(f"{params.path}: geometry.neck_base.cable_pass.from_edge: expected 0 <= from < to "
                             f"<= the plate's length, got {[c0, c1]}")
    cw = cable.num("width", positive=True)
    mh = fl.node("mount_holes")
    mx, my = mh.vec("at", 2)
    if params.purchased(STANDOFF).num("length") != bay:
        raise ParameterError(f"{params.path}: geometry.neck_base.bay_height: {bay} differs from the length of the "
                             f"standoffs ({STANDOFF}: {params.purchased(STANDOFF).num('length')})")
    y_up = gap / 2 + ut / 2
    upright_screws = [(sx * ul / 4, sy * y_up) for sx in (-1, 1) for sy in (-1, 1)]

    plate = geom.cut(geom.box(-L / 2, L / 2, -W / 2, W / 2, -T, 0),
                     *[geom.cyl("z", m3, -T - 1, 1, c) for c in corners + upright_screws],
                     geom.box(-L / 2 + c0, -L / 2 + c1, -cw / 2, cw / 2, -T - 1, 1))  # board cable pass-through
    flange = geom.cut(geom.box(-fl.num("length") / 2, fl.num("length") / 2, -fl.num("width") / 2, fl.num("width") / 2, 0, ft),
                      *[geom.cyl("z", m3, -1, ft + 1, c) for c in corners],
                      *[geom.cyl("z", mh.num("diameter", positive=True), -1, ft + 1, (sx * mx, sy * my))
                        for sx in (-1, 1) for sy in (-1, 1)],
                      *board_stack.flange_holes(params, ft))
    z_flange = -T - bay - ft

    bearing = params.purchased(params.drive("neck_pitch").text("bearing"))
    bw, bo = bearing.num("width"), bearing.num("outside")
    height = hp + bo / 2 + 5
    # Left upright in its design frame; the right one is the same part turned half a turn about z.
    y_face = gap / 2 + ut
    upright = geom.cut(geom.box(-ul / 2, ul / 2, gap / 2, y_face, 0, height),
                       geom.cyl("y", bearing.num("bore") + 2 * up.num("shaft_clearance", positive=True),
                                gap / 2 - 1, y_face + 1, (0, hp)),
                       geom.cyl("y", bo, y_face - bw, y_face + 1, (0, hp)),
                       *[geom.cyl("z", 3.0, -1, 6, (sx * ul / 4, y_up)) for sx in (-1, 1)],
                       *[geom.cyl("y", 3.0, y_face - 8, y_face + 1, (fx, hp - fy))
                         for fx, fy in mounts.mount_fixings(params, "neck_pitch")])
    upright = geom.single_solid(upright, "neck_upright")

    parts = [
        Part("neck_base_plate", "neck_base_plate", "neck_base", "machined", geom.single_solid(plate, "plate"),
             material="aluminium-6082", color=ALUMINIUM),
        Part("neck_base_flange", "neck_base_flange", "neck_base", "machined", geom.single_solid(flange, "flange"),
             loc(z=z_flange), material="aluminium-6082", color=ALUMINIUM, note=board_stack.FLANGE_NOTE),
        Part("neck_upright_left", "neck_upright", "neck_base", "machined", upright, material="aluminium-6082", color=ALUMINIUM,
             note=UPRIGHT_NOTE),
        Part("neck_upright_right", "neck_upright", "neck_base", "machined", upright, loc(rz=180),
             material="aluminium-6082", color=ALUMINIUM, note=UPRIGHT_NOTE),
    ]
    for i, (x, y) in enumerate(corners):
        parts.append(purchased.standoff(params, f"base_standoff_{i}", STANDOFF, "neck_base", loc(x, y, -T - bay)))
        parts.append(purchased.screw(params, f"base_plate_screw_{i}", SCREW, "neck_base", loc(x, y, 0, rx=180)))
        parts.append(purchased.screw(params, f"base_flange_screw_{i}", SCREW, "neck_base", loc(x, y, z_flange)))
    for i, (x, y) in enumerate(upright_screws):
        parts.append(purchased.screw(params, f"upright_screw_{i}", SCREW, "neck_base", loc(x, y, -T)))
    # Pitch bearings sit in the uprights' outer recesses; the drive is bolted on the left upright.
    y_out = gap / 2 + ut
    parts.append(purchased.bearing(params, "neck_pitch_bearing_left", params.drive("neck_pitch").text("bearing"), "neck_base",
                                   loc(0, y_out - bw, hp, rx=-90)))
    parts.append(purchased.bearing(params, "neck_pitch_bearing_right", params.drive("neck_pitch").text("bearing"), "neck_base",
                                   loc(0, -y_out + bw, hp, rx=90)))
    gear = params.purchased(params.drive("neck_pitch").text("gearhead"))
    pt = mounts.mount_thickness(params, "neck_pitch")
    mount = mounts.mount_plate(params, "neck_pitch", mounts.mount_outline(params, "neck_pitch"), gear.num("diameter"))
    parts.append(Part("neck_pitch_motor_mount", "motor_mount_neck_pitch", "neck_base", "machined", mount,
                      loc(0, y_out, hp, rx=-90), material="aluminium-6082", color=ALUMINIUM,
                      note=mounts.mount_note(params, "neck_pitch")))
    parts += gearhead_screws.screws(params, "neck_pitch", "neck_base", loc(0, y_out, hp, rx=-90), gear.num("diameter"), pt)
    for i, (fx, fy) in enumerate(mounts.mount_fixings(params, "neck_pitch")):   # heads on the plate, shanks into the upright (-y)
        parts.append(purchased.screw(params, f"pitch_mount_screw_{i}", mounts.FIXING_SCREW, "neck_base",
                                     loc(fx, y_out + pt, hp - fy, rx=90)))
    parts += purchased.drive_stack(params, "neck_pitch", "neck_base", loc(0, y_out + pt, hp, rx=-90))
    parts.append(purchased.joint_encoder(params, "neck_pitch_joint_encoder", "neck_base", loc(0, -y_out - 1, hp, rx=90)))
    return parts


def _pitch_stage(params: HeadParameters) -> list[Part]:
    """Pitch stage in the neck_pitch_link frame (origin on the pitch axis)."""
    g = params.geometry("neck_pitch_stage")
    b, lug = g.node("body"), g.node("lug")
    bl, bw, bh = b.num("length", positive=True), b.num("width", positive=True), b.num("height", positive=True)
    lt, lw, span = lug.num("thickness", positive=True), lug.num("width", positive=True), lug.num("span", positive=True)
    up = params.geometry("neck_base", "upright")
    y_out = up.num("gap") / 2 + up.num("thickness")
    zr = params.joints["neck_roll"].origin[2]
    gear = params.purchased(params.drive("neck_pitch").text("gearhead"))
    bearing = params.purchased(params.drive("neck_roll").text("bearing"))
    pitch_bore = params.purchased(params.drive("neck_pitch").text("bearing")).num("bore", positive=True)
    pitch_plate = mounts.mount_thickness(params, "neck_pitch")   # the gearhead's flange, so its shaft's reach
    roll_fixings = mounts.mount_fixings(params, "neck_roll")
    x_out = span / 2 + lt
    stage = geom.union(
        geom.box(-bl / 2, bl / 2, -bw / 2, bw / 2, -bh / 2, bh / 2),
        geom.box(-x_out, x_out, -lw / 2, lw / 2, bh / 2 - 4, bh / 2),
        geom.box(span / 2, x_out, -lw / 2, lw / 2, bh / 2 - 4, zr + lw / 2),
        geom.box(-x_out, -span / 2, -lw / 2, lw / 2, bh / 2 - 4, zr + lw / 2),
        geom.cyl("y", pitch_bore, bw / 2 - 1, y_out),          # pitch shafts, integral with the stage
        geom.cyl("y", pitch_bore, -y_out, -bw / 2 + 1),
    )
    stage = geom.cut(stage,
                     geom.cyl("y", gear.num("shaft_diameter"), y_out - gear.num("shaft_length") + pitch_plate, y_out + 1),
                     geom.cyl("x", bearing.num("outside"), span / 2 - 1, x_out + 1, (0, zr)),
                     geom.cyl("x", bearing.num("outside"), -x_out - 1, -span / 2 + 1, (0, zr)),
                     *[geom.cyl("x", 3.0, -x_out - 1, -span / 2 + 1, (fy, zr + fx)) for fx, fy in roll_fixings])
    parts = [Part("neck_pitch_stage", "neck_pitch_stage", "neck_pitch_link", "machined", geom.single_solid(stage, "pitch stage"),
                  material="aluminium-6082", color=ALUMINIUM, note=PITCH_STAGE_NOTE)]
    key = params.drive("neck_roll").text("bearing")
    parts.append(purchased.bearing(params, "neck_roll_bearing_front", key, "neck_pitch_link", loc(span / 2, 0, zr, ry=90)))
    parts.append(purchased.bearing(params, "neck_roll_bearing_rear", key, "neck_pitch_link", loc(-span / 2, 0, zr, ry=-90)))
    roll_gear = params.purchased(params.drive("neck_roll").text("gearhead"))
    rd = roll_gear.num("diameter")
    rt = mounts.mount_thickness(params, "neck_roll")
    bottom = min(fx for fx, _ in roll_fixings) - mounts.mount(params, "neck_roll").num("margin", positive=True)
    if zr + bottom < bh / 2 - 4:
        raise ParameterError(f"{params.path}: joints.neck_roll.origin[2]: {zr} leaves the roll motor mount's screws "
                             f"below the rear lug")
    parts.append(Part("neck_roll_motor_mount", "motor_mount_neck_roll", "neck_pitch_link", "machined",
                      mounts.mount_plate(params, "neck_roll", (bottom, rd / 2, -lw / 2, lw / 2), rd),
                      loc(-x_out, 0, zr, ry=-90),
                      material="aluminium-6082", color=ALUMINIUM, note=mounts.mount_note(params, "neck_roll")))
    parts += gearhead_screws.screws(params, "neck_roll", "neck_pitch_link", loc(-x_out, 0, zr, ry=-90), rd, rt)
    for i, (fx, fy) in enumerate(roll_fixings):   # heads on the plate, shanks into the lug (+x)
        parts.append(purchased.screw(params, f"roll_mount_screw_{i}", mounts.FIXING_SCREW, "neck_pitch_link",
                                     loc(-x_out - rt, fy, zr + fx, ry=90)))
    parts += purchased.drive_stack(params, "neck_roll", "neck_pitch_link", loc(-x_out - rt, 0, zr, ry=-90))
    parts.append(purchased.joint_encoder(params, "neck_roll_joint_encoder", "neck_pitch_link", loc(x_out + 1, 0, zr, ry=90)))
    return parts


def _roll_stage(params: HeadParameters) -> list[Part]:
    """Roll stage in the neck_roll_link frame (origin on the roll axis), carrying the fixed yaw shaft and pulley."""
    b = params.geometry("neck_roll_stage", "body")
    bl, bw, bh = b.num("length", positive=True), b.num("width", positive=True), b.num("height", positive=True)
    lug = params.geometry("neck_pitch_stage", "lug")
    x_out = lug.num("span") / 2 + lug.num("thickness")
    zy = params.joints["neck_yaw"].origin[2]
    gear = params.purchased(params.drive("neck_roll").text("gearhead"))
    yaw_bearing = params.purchased(params.drive("neck_yaw").text("bearing"))
    shaft = yaw_bearing.num("bore")
    roll_bore = params.purchased(params.drive("neck_roll").text("bearing")).num("bore", positive=True)
    stage = geom.union(geom.box(-bl / 2, bl / 2, -bw / 2, bw / 2, -bh / 2, bh / 2),
                       geom.cyl("x", roll_bore, bl / 2 - 1, x_out), geom.cyl("x", roll_bore, -x_out, -bl / 2 + 1),
                       geom.cyl("z", shaft, bh / 2 - 1, zy))
    roll_plate = mounts.mount_thickness(params, "neck_roll")   # the gearhead's flange, so its shaft's reach
    stage = geom.cut(stage, geom.cyl("x", gear.num("shaft_diameter"), -x_out - 1,
                                      -x_out + gear.num("shaft_length") - roll_plate))
    teeth = int(params.geometry("pulleys", "yaw").num("joint_teeth", positive=True))
    return [
        Part("neck_roll_stage", "neck_roll_stage", "neck_roll_link", "machined", geom.single_solid(stage, "roll stage"),
             material="aluminium-6082", color=ALUMINIUM),
        Part("neck_yaw_joint_pulley", f"pulley_mxl_{teeth}T_bore{shaft:g}", "neck_roll_link", "machined",
             mounts.pulley(params, teeth, shaft), loc(z=zy - yaw_pulley_drop(params)), material="aluminium-6082",
             color=ALUMINIUM, note=mounts.pulley_note(params, teeth, shaft)),
    ]


def yaw_pulley_drop(params: HeadParameters) -> float:
    """Depth of the yaw pulleys' lower face below the yaw joint frame: pulleys.plate_gap under the head floor."""
    return (params.geometry("head", "floor").num("thickness") + mounts.plate_gap(params)
            + params.geometry("pulleys").num("width", positive=True))


def build(params: HeadParameters) -> list[Part]:
    # The yaw pulleys hang between the roll stage and the head floor.
    zy = params.joints["neck_yaw"].origin[2]
    top = params.geometry("neck_roll_stage", "body").num("height") / 2
    if zy - yaw_pulley_drop(params) - top < params.geometry("clearances").num("minimum"):
        raise ParameterError(f"{params.path}: joints.neck_yaw.origin[2]: {zy} leaves no room for the yaw pulleys "
                             f"above the roll stage (top at {top})")
    return _base(params) + _pitch_stage(params) + _roll_stage(params)
