# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Head frame (floor, side plates, back plate, top bar) with the yaw and eye-tilt drives it carries."""
from __future__ import annotations

from .. import geom
from ..params import HeadParameters
from . import gearhead_screws, head_joins, mounts, neck, purchased
from .base import ALUMINIUM, PRINTED, Part, loc

YAW_FIXINGS = tuple((sx * 10.0, sy * 10.0) for sx in (-1, 1) for sy in (-1, 1))   # about the yaw motor axis
YAW_SLOT = 2.0
YAW_MOUNT_NOTE = "3.4 x 5.4 slots along x: M3 into the floor, slide to tension the belt; 4 x 2.2 on the gearhead's bolt circle"
YAW_GEARHEAD_SCREW = "iso4762-M2x6"
# The tilt gearhead's flange bears on the left side plate's inner face; its screws come from outside.


def build(params: HeadParameters) -> list[Part]:
    h = params.geometry("head")
    fl, sp, bp, tb = h.node("floor"), h.node("side_plate"), h.node("back_plate"), h.node("top_bar")
    x0, x1, hw, ft = fl.num("x_min"), fl.num("x_max"), fl.num("half_width", positive=True), fl.num("thickness", positive=True)
    st, sx0, sx1, sh = sp.num("thickness", positive=True), sp.num("x_min"), sp.num("x_max"), sp.num("height", positive=True)
    bt, bh = bp.num("thickness", positive=True), bp.num("height", positive=True)
    inner = hw - st
    tilt = params.joints["eyes_tilt"].origin
    tx, tz = tilt[0], tilt[2]
    ym = h.num("yaw_motor_x")
    tm = h.node("tilt_motor")
    tmx, tmz = tm.num("x"), tm.num("z")
    yaw_bearing = params.purchased(params.drive("neck_yaw").text("bearing"))
    tilt_bearing = params.purchased(params.drive("eyes_tilt").text("bearing"))
    al = dict(material="aluminium-6082", color=ALUMINIUM)
    joins = head_joins.build(params)

    yaw_gear = params.purchased(params.drive("neck_yaw").text("gearhead"))
    tilt_gear = params.purchased(params.drive("eyes_tilt").text("gearhead"))
    tilt_flange = loc(tmx, hw, tmz, rx=90)   # gearhead_screws' flange frame: z from the plate's outer face inwards
    floor = geom.cut(geom.box(x0, x1, -hw, hw, -ft, 0),
                     geom.cyl("z", yaw_bearing.num("outside"), -ft - 1, 1),
                     geom.cyl("z", 8, -ft - 1, 1, (ym, 0)), *joins.holes["head_floor"],
                     *[geom.cyl("z", 3.0, -ft - 1, 1, (ym + fx, fy)) for fx, fy in YAW_FIXINGS],
                     *[t.moved(loc(ym, 0, 0)) for t in gearhead_screws.head_pockets(yaw_gear.num("diameter"), YAW_SLOT)])
    # Left side plate in its design frame; the right plate is its mirror image.
    face_z = h.vec("face_screw_z", 2)
    side = geom.cut(geom.box(sx0, sx1, inner, hw, 0, sh),
                    geom.cyl("y", tilt_bearing.num("outside"), inner - 1, hw + 1, (tx, tz)),
                    geom.cyl("y", tilt_gear.num("shaft_diameter") + 2, inner - 1, hw + 1, (tmx, tmz)),
                    *[t.moved(tilt_flange) for t in gearhead_screws.holes(tilt_gear.num("diameter"), st)],
                    # M3 tapped holes for the face plate screws, modelled at the thread's size like every
                    # tapped hole of the head (the drawing's note gives the tap drill)
                    *[geom.cyl("x", 3.0, sx1 - 8, sx1 + 1, (inner + st / 2, z)) for z in face_z],
                    *joins.holes["head_side_plate"])
    side = geom.single_solid(side, "side plate")
    side_right = side.mirror("XZ")
    back = geom.single_solid(geom.cut(geom.box(x0, x0 + bt, -inner, inner, 0, bh), *joins.holes["head_back_plate"]),
                             "back plate")
    top = geom.box(tb.num("x"), tb.num("x") + tb.num("width", positive=True), -inner, inner, sh - tb.num("thickness"), sh)
    top = geom.single_solid(geom.cut(top, *joins.holes["head_top_bar"]), "top bar")
    notes = head_joins.NOTES

    parts = [
        Part("head_floor", "head_floor", "head_frame", "machined", geom.single_solid(floor, "floor"),
             note=notes["head_floor"], **al),
        Part("head_side_plate_left", "head_side_plate_left", "head_frame", "machined", side,
             note=notes["head_side_plate"], **al),
        Part("head_side_plate_right", "head_side_plate_right", "head_frame", "machined", side_right,
             note=notes["head_side_plate"], **al),
        Part("head_back_plate", "head_back_plate", "head_frame", "machined", back, note=notes["head_back_plate"], **al),
        Part("head_top_bar", "head_top_bar", "head_frame", "machined", top, note=notes["head_top_bar"], **al),
        purchased.bearing(params, "neck_yaw_bearing", params.drive("neck_yaw").text("bearing"), "head_frame",
                          loc(z=-ft)),
        purchased.bearing(params, "eyes_tilt_bearing_left", params.drive("eyes_tilt").text("bearing"), "head_frame",
                          loc(tx, inner, tz, rx=-90)),
        purchased.bearing(params, "eyes_tilt_bearing_right", params.drive("eyes_tilt").text("bearing"), "head_frame",
                          loc(tx, -inner, tz, rx=90)),
        purchased.joint_encoder(params, "neck_yaw_joint_encoder", "head_frame", loc(0, 0, 1)),
        purchased.joint_encoder(params, "eyes_tilt_joint_encoder", "head_frame", loc(tx, -hw - 1, tz, rx=90)),
    ]
    # Yaw drive: gearhead flange on a mount plate on the floor, output shaft down to the motor pulley.
    # Four M3 through slots into the floor: the plate slides along x to tension the belt.
    parts.append(Part("neck_yaw_motor_mount", "motor_mount_neck_yaw", "head_frame", "machined",
                      mounts.mount_plate((-14, 14, -14, 14), 3, 8, yaw_gear.num("diameter"), YAW_FIXINGS, slot=YAW_SLOT,
                                         counterbores=False),
                      loc(ym, 0, 0), note=YAW_MOUNT_NOTE, **al))
    for i, (fx, fy) in enumerate(YAW_FIXINGS):
        parts.append(purchased.screw(params, f"yaw_mount_screw_{i}", mounts.FIXING_SCREW, "head_frame",
                                     loc(ym + fx, fy, 3, rx=180)))
    parts += purchased.drive_stack(params, "neck_yaw", "head_frame", loc(ym, 0, 3))
    # The 3 mm plate has no room for counterbores: the screw heads sit under it, in slotted pockets in the floor.
    parts += gearhead_screws.screws(params, "neck_yaw", "head_frame", loc(ym, 0, 0), yaw_gear.num("diameter"), 3,
                                    key=YAW_GEARHEAD_SCREW, counterbored=False)
    yaw_teeth = int(params.geometry("pulleys", "yaw").num("motor_teeth", positive=True))
    parts.append(Part("neck_yaw_motor_pulley", f"pulley_mxl_{yaw_teeth}T_bore{yaw_gear.num('shaft_diameter'):g}", "head_frame",
                      "machined", mounts.pulley(params, yaw_teeth, yaw_gear.num("shaft_diameter")),
                      loc(ym, 0, -neck.yaw_pulley_drop(params)),
                      note=mounts.pulley_note(params, yaw_teeth, yaw_gear.num("shaft_diameter")), **al))
    # Tilt drive: gearhead flange on the inside of the left side plate, pulley outside, motor held by a clamp.
    tilt_motor = params.purchased(params.drive("eyes_tilt").text("motor"))
    parts += purchased.drive_stack(params, "eyes_tilt", "head_frame", loc(tmx, inner, tmz, rx=90))
    parts += gearhead_screws.screws(params, "eyes_tilt", "head_frame", tilt_flange, tilt_gear.num("diameter"), st)
    tilt_teeth = int(params.geometry("pulleys", "tilt").num("motor_teeth", positive=True))
    parts.append(Part("eyes_tilt_motor_pulley", f"pulley_mxl_{tilt_teeth}T_bore{tilt_gear.num('shaft_diameter'):g}",
                      "head_frame", "machined", mounts.pulley(params, tilt_teeth, tilt_gear.num("shaft_diameter")),
                      loc(tmx, hw + 1, tmz, rx=-90),
                      note=mounts.pulley_note(params, tilt_teeth, tilt_gear.num("shaft_diameter")), **al))
    y_motor = inner - tilt_gear.num("length") - tilt_motor.num("length") / 2
    clamp = geom.cut(geom.box(x0 + bt, tmx + 10, y_motor - 5, y_motor + 5, tmz - 12, tmz + 12),
                     geom.cyl("y", tilt_motor.num("diameter"), y_motor - 6, y_motor + 6, (tmx, tmz)))
    parts.append(Part("eyes_tilt_motor_clamp", "eyes_tilt_motor_clamp", "head_frame", "printed",
                      geom.single_solid(clamp, "tilt motor clamp"), material="petg-printed", color=PRINTED))
    return parts + joins.screws
