# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Head frame (floor, side plates, back plate, top bar) with the yaw and eye-tilt drives it carries."""
from __future__ import annotations

import math

import cadquery as cq

from robogene_head_model.params import HeadParameters, Node, ParameterError

from .. import geom
from . import (gearhead_screws, head_joins, joint_encoders, mounts, neck, purchased, tilt_bearings, tilt_jackshaft,
               tilt_stops, yaw_bearings)
from .base import ALUMINIUM, DARK, Part, loc
YAW_GEARHEAD_SCREW = "iso4762-M2x6"


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
    tilt_bearing = params.purchased(params.drive("eyes_tilt").text("bearing"))
    al = dict(material="aluminium-6082", color=ALUMINIUM)
    joins = head_joins.build(params)

    yaw_gear = params.purchased(params.drive("neck_yaw").text("gearhead"))
    yaw_fixings, yaw_slot = mounts.mount_fixings(params, "neck_yaw"), mounts.mount_slot(params, "neck_yaw")
    yaw_plate = mounts.mount_thickness(params, "neck_yaw")
    m3 = params.purchased(mounts.FIXING_SCREW).num("diameter")   # tapped holes are drawn at the thread
    # the yaw bearings' boss stands on the floor (yaw_bearings)
    floor = geom.cut(geom.union(geom.box(x0, x1, -hw, hw, -ft, 0), yaw_bearings.boss(params)),
                     *yaw_bearings.housing_tools(params),
                     *_yaw_hub_slot(params, yaw_gear.num("shaft_diameter"), ym, -ft - 1, 1), *joins.holes["head_floor"],
                     *[geom.cyl("z", m3, -ft - 1, 1, (ym + fx, fy)) for fx, fy in yaw_fixings],
                     *[t.moved(loc(ym, 0, 0)) for t in gearhead_screws.head_pockets(params, yaw_gear.num("diameter"),
                                                                                    yaw_slot)],
                     *joint_encoders.face_holes(params, joint_encoders.ends(params)["neck_yaw"]))   # the yaw encoder's bracket
    # Left side plate in its design frame; the right plate is its mirror image.
    face_z = h.vec("face_screw_z", 2)
    stop_pins, stop_holes = tilt_stops.pins(params, inner, (tx, tz), "head_frame")
    tap_depth = head_joins.tap_depth(params)
    side = geom.cut(geom.box(sx0, sx1, inner, hw, 0, sh),
                    *tilt_jackshaft.side_plate_tools(params),   # the tilt motor pulley's stage (slots: belt tension)
                    # M3 tapped holes for the face plate screws, modelled at the thread's size like every
                    # tapped hole of the head (the drawing's note gives the tap drill)
                    *[geom.cyl("x", m3, sx1 - tap_depth, sx1 + 1, (inner + st / 2, z)) for z in face_z],
                    *joins.holes["head_side_plate"], *stop_holes)
    # The left plate's through-bore holds the floating tilt bearing; the right plate's boss the fixed one
    # (tilt_bearings); the tilt encoder's bracket screws into the right plate's outer face beside the boss.
    side_right = geom.single_solid(geom.cut(geom.union(side.mirror("XZ"), tilt_bearings.right_boss(params)),
                                            *tilt_bearings.right_seat_tools(params),
                                            *joint_encoders.face_holes(params, joint_encoders.ends(params)["eyes_tilt"])),
                                   "right side plate")
    side = geom.single_solid(geom.cut(side, geom.cyl("y", tilt_bearing.num("outside"), inner - 1, hw + 1, (tx, tz))),
                             "side plate")
    back = geom.single_solid(geom.cut(geom.box(x0, x0 + bt, -inner, inner, 0, bh), *joins.holes["head_back_plate"]),
                             "back plate")
    top = geom.box(tb.num("x"), tb.num("x") + tb.num("width", positive=True), -inner, inner, sh - tb.num("thickness"), sh)
    top = geom.single_solid(geom.cut(top, *joins.holes["head_top_bar"]), "top bar")
    notes = head_joins.notes(params)

    parts = [
        Part("head_floor", "head_floor", "head_frame", "machined", geom.single_solid(floor, "floor"),
             note=notes["head_floor"] + " " + yaw_bearings.HOUSING_NOTE, **al),
        Part("head_side_plate_left", "head_side_plate_left", "head_frame", "machined", side,
             note=notes["head_side_plate"] + " " + tilt_stops.PIN_NOTE, **al),
        Part("head_side_plate_right", "head_side_plate_right", "head_frame", "machined", side_right,
             note=notes["head_side_plate"] + " " + tilt_stops.PIN_NOTE + " " + tilt_bearings.BOSS_NOTE, **al),
        Part("head_back_plate", "head_back_plate", "head_frame", "machined", back, note=notes["head_back_plate"], **al),
        Part("head_top_bar", "head_top_bar", "head_frame", "machined", top, note=notes["head_top_bar"], **al),
        *yaw_bearings.head_parts(params),
        purchased.bearing(params, "eyes_tilt_bearing_left", params.drive("eyes_tilt").text("bearing"), "head_frame",
                          loc(tx, inner, tz, rx=-90)),
        *[p for p in tilt_bearings.right_parts(params) if p.link == "head_frame"],
    ]
    # Yaw drive: gearhead flange on a mount plate on the floor, output shaft down to the motor pulley.
    # Four M3 through slots into the floor: the plate slides along x to tension the belt.
    parts.append(Part("neck_yaw_motor_mount", "motor_mount_neck_yaw", "head_frame", "machined",
                      mounts.mount_plate(params, "neck_yaw", mounts.mount_outline(params, "neck_yaw"),
                                         yaw_gear.num("diameter"), counterbores=False),
                      loc(ym, 0, 0), note=mounts.mount_note(params, "neck_yaw"), **al))
    for i, (fx, fy) in enumerate(yaw_fixings):
        parts.append(purchased.screw(params, f"yaw_mount_screw_{i}", mounts.FIXING_SCREW, "head_frame",
                                     loc(ym + fx, fy, yaw_plate, rx=180)))
    parts += purchased.drive_stack(params, "neck_yaw", "head_frame", loc(ym, 0, yaw_plate))
    # The thin plate has no room for counterbores: the screw heads sit under it, in slotted pockets in the floor.
    parts += gearhead_screws.screws(params, "neck_yaw", "head_frame", loc(ym, 0, 0), yaw_gear.num("diameter"),
                                    yaw_plate, key=YAW_GEARHEAD_SCREW, counterbored=False)
    # The motor pulleys' hubs reach back along the gearhead shafts, through the floor and the mount plate here.
    width = mounts.pulley_width(params, "neck_yaw")
    drop = neck.yaw_pulley_drop(params)
    yaw_teeth, yaw_bore = int(params.geometry("pulleys", "yaw").num("motor_teeth", positive=True)), yaw_gear.num("shaft_diameter")
    parts.append(Part("neck_yaw_motor_pulley", f"pulley_mxl_{yaw_teeth}T_bore{yaw_bore:g}", "head_frame", "machined",
                      mounts.pulley(params, "neck_yaw", yaw_teeth, yaw_bore,
                                    mounts.hub_length(params, drop - width + yaw_plate)),
                      loc(ym, 0, -drop), note=mounts.pulley_note(params, "neck_yaw", yaw_teeth, yaw_bore, hub=True), **al))
    # Tilt drive: clamped in the jackshaft's housing on the inside of the left side plate, the motor pulley on the
    # jackshaft outside it (tilt_jackshaft)
    parts += tilt_jackshaft.build(params)
    return parts + belt_parts(params) + joins.screws + stop_pins


def _yaw_hub_slot(params: HeadParameters, bore: float, ym: float, z0: float, z1: float) -> list[cq.Shape]:
    """The floor's passage for the yaw motor pulley's hub: a slot along x, as far as the mount plate slides."""
    d, slot = mounts.hub_hole(params, bore), mounts.mount_slot(params, "neck_yaw")
    pilot = params.geometry("motor_mounts").num("pilot_hole", positive=True)
    if d > pilot:
        raise ParameterError(f"{params.path}: geometry.motor_mounts.pilot_hole: {pilot:g} is too small for the yaw "
                             f"motor pulley's hub, which needs {d:g}")
    tools = [geom.cyl("z", d, z0, z1, (ym - slot / 2, 0))]
    if slot > 0:
        tools += [geom.cyl("z", d, z0, z1, (ym + slot / 2, 0)), geom.box(ym - slot / 2, ym + slot / 2, -d / 2, d / 2, z0, z1)]
    return tools


def belt_parts(params: HeadParameters) -> list[Part]:
    """The two belt loops, on the head frame, which carries both drives' motors. Each joint pulley turns about
    its own axis, the joint's, so the loop around it is the same at every joint angle: one fixed envelope."""
    h = params.geometry("head")
    hw = h.node("floor").num("half_width")
    belts = {joint: (key, teeth) for key, joint, teeth in mounts.belts(params)}
    yaw, tilt = params.geometry("pulleys", "yaw"), params.geometry("pulleys", "tilt")
    ym = h.num("yaw_motor_x")
    tx, _, tz = params.joints["eyes_tilt"].origin
    tmx, tmz = h.node("tilt_motor").num("x"), h.node("tilt_motor").num("z")
    # pulley frames: the yaw pulleys' z 0..width from the drop below the floor, the tilt pulleys' along +y from
    # 1 mm outside the left side plate; the loop's x axis points from the joint pulley to the motor pulley
    loops = [("neck_yaw", abs(ym), yaw, loc(0, 0, -neck.yaw_pulley_drop(params), rz=0 if ym > 0 else 180)),
             ("eyes_tilt", math.hypot(tmx - tx, tmz - tz), tilt,
              loc(tx, hw + mounts.plate_gap(params), tz, ry=math.degrees(math.atan2(-(tmz - tz), tmx - tx)), rx=-90))]
    out = []
    for joint, distance, teeth, placement in loops:
        key, belt_teeth = belts[joint]
        shape = mounts.belt_loop(params, joint, distance, int(teeth.num("joint_teeth")), int(teeth.num("motor_teeth")))
        stock = params.purchased(mounts.belt_key(params, joint))
        out.append(Part(f"{joint}_belt", key, "head_frame", "purchased", shape, placement,
                        mass=belt_teeth * mounts.belt_pitch(params, joint) / 1000 * stock.num("mass_per_metre"), color=DARK,
                        note="belt back around the pulleys; its teeth sit in the pulley envelopes"))
    return out
