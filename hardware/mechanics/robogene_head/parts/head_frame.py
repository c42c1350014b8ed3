# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Head frame (floor, side plates, back plate, top bar) with the yaw and eye-tilt drives it carries."""
from __future__ import annotations

import math

import cadquery as cq

from robogene_head_model.params import HeadParameters

from .. import geom
from . import (head_joins, joint_encoders, mounts, neck, purchased, tilt_bearings, tilt_jackshaft, tilt_stops,
               yaw_bearings, yaw_jackshaft)
from .base import ALUMINIUM, DARK, Part, loc


def build(params: HeadParameters) -> list[Part]:
    h = params.geometry("head")
    fl, sp, bp, tb = h.node("floor"), h.node("side_plate"), h.node("back_plate"), h.node("top_bar")
    x0, x1, hw, ft = fl.num("x_min"), fl.num("x_max"), fl.num("half_width", positive=True), fl.num("thickness", positive=True)
    st, sx0, sx1, sh = sp.num("thickness", positive=True), sp.num("x_min"), sp.num("x_max"), sp.num("height", positive=True)
    bt, bh = bp.num("thickness", positive=True), bp.num("height", positive=True)
    inner = hw - st
    tilt = params.joints["eyes_tilt"].origin
    tx, tz = tilt[0], tilt[2]
    tilt_bearing = params.purchased(params.drive("eyes_tilt").text("bearing"))
    al = dict(material="aluminium-6082", color=ALUMINIUM)
    joins = head_joins.build(params)

    m3 = params.purchased(mounts.FIXING_SCREW).num("diameter")   # tapped holes are drawn at the thread
    # the yaw bearings' boss stands on the floor (yaw_bearings); the yaw jackshaft's housing on its top face, the
    # jackshaft through it and the housing's fixings in slots along the belt (yaw_jackshaft)
    floor = geom.cut(geom.union(geom.box(x0, x1, -hw, hw, -ft, 0), yaw_bearings.boss(params)),
                     *yaw_bearings.housing_tools(params), *yaw_jackshaft.floor_tools(params), *joins.holes["head_floor"],
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
    # Yaw drive: clamped in the jackshaft's housing on the floor, the motor pulley on the jackshaft under it
    parts += yaw_jackshaft.build(params)
    # Tilt drive: clamped in the jackshaft's housing on the inside of the left side plate, the motor pulley on the
    # jackshaft outside it (tilt_jackshaft)
    parts += tilt_jackshaft.build(params)
    return parts + belt_parts(params) + joins.screws + stop_pins


def belt_parts(params: HeadParameters) -> list[Part]:
    """The two belt loops, on the head frame, which carries both drives' motors. Each joint pulley turns about
    its own axis, the joint's, so the loop around it is the same at every joint angle: one fixed envelope."""
    h = params.geometry("head")
    hw = h.node("floor").num("half_width")
    belts = {joint: (key, teeth) for key, joint, teeth in mounts.belts(params)}
    yaw, tilt = params.geometry("pulleys", "yaw"), params.geometry("pulleys", "tilt")
    yx, yy = yaw_jackshaft.axis(params)
    tx, _, tz = params.joints["eyes_tilt"].origin
    tmx, tmz = h.node("tilt_motor").num("x"), h.node("tilt_motor").num("z")
    # pulley frames: the yaw pulleys' z 0..width from the drop below the floor, the tilt pulleys' along +y from
    # 1 mm outside the left side plate; the loop's x axis points from the joint pulley to the motor pulley
    loops = [("neck_yaw", yaw_jackshaft.centre_distance(params), yaw,
              loc(0, 0, -neck.yaw_pulley_drop(params), rz=math.degrees(math.atan2(yy, yx)))),
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
