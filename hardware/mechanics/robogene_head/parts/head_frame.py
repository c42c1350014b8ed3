# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Head frame (floor, side plates, back plate, top bar) with the yaw and eye-tilt drives it carries."""
from __future__ import annotations

import math

import cadquery as cq

from robogene_head_model.params import HeadParameters, Node, ParameterError

from .. import geom
from . import gearhead_screws, head_joins, joint_encoders, mounts, neck, purchased, tilt_bearings, tilt_stops, yaw_bearings
from .base import ALUMINIUM, DARK, PRINTED, Part, loc
YAW_GEARHEAD_SCREW = "iso4762-M2x6"
CLAMP_SCREW = "iso7380-M3x8"   # the tilt motor clamp's two screws into the back plate (geometry.head.tilt_motor_clamp)
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
    tilt_bearing = params.purchased(params.drive("eyes_tilt").text("bearing"))
    al = dict(material="aluminium-6082", color=ALUMINIUM)
    joins = head_joins.build(params)

    yaw_gear = params.purchased(params.drive("neck_yaw").text("gearhead"))
    tilt_gear = params.purchased(params.drive("eyes_tilt").text("gearhead"))
    tilt_flange = loc(tmx, hw, tmz, rx=90)   # gearhead_screws' flange frame: z from the plate's outer face inwards
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
                    geom.cyl("y", mounts.hub_hole(params, tilt_gear.num("shaft_diameter")), inner - 1, hw + 1, (tmx, tmz)),
                    *[t.moved(tilt_flange) for t in gearhead_screws.holes(params, tilt_gear.num("diameter"), st)],
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
    back = geom.single_solid(geom.cut(geom.box(x0, x0 + bt, -inner, inner, 0, bh), *joins.holes["head_back_plate"],
                                      *tilt_clamp_back_holes(params)), "back plate")
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
    # Tilt drive: gearhead flange on the inside of the left side plate, pulley outside with its hub through the
    # plate, motor held by a clamp.
    tilt_motor = params.purchased(params.drive("eyes_tilt").text("motor"))
    gap = mounts.plate_gap(params)
    parts += purchased.drive_stack(params, "eyes_tilt", "head_frame", loc(tmx, inner, tmz, rx=90))
    parts += gearhead_screws.screws(params, "eyes_tilt", "head_frame", tilt_flange, tilt_gear.num("diameter"), st)
    tilt_teeth, tilt_bore = int(params.geometry("pulleys", "tilt").num("motor_teeth", positive=True)), tilt_gear.num("shaft_diameter")
    parts.append(Part("eyes_tilt_motor_pulley", f"pulley_mxl_{tilt_teeth}T_bore{tilt_bore:g}", "head_frame", "machined",
                      mounts.pulley(params, "eyes_tilt", tilt_teeth, tilt_bore,
                                    mounts.hub_length(params, hw + gap - inner)),
                      loc(tmx, hw + gap + mounts.pulley_width(params, "eyes_tilt"), tmz, rx=90),   # body y hw+gap..hw+gap+width, hub towards -y
                      note=mounts.pulley_note(params, "eyes_tilt", tilt_teeth, tilt_bore, hub=True), **al))
    clamp, clamp_screws = _tilt_motor_clamp(params, inner, x0 + bt, tmx, tmz,
                                            inner - tilt_gear.num("length") - tilt_motor.num("length") / 2)
    parts.append(clamp)
    return parts + clamp_screws + belt_parts(params) + joins.screws + stop_pins


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


def _clamp(params: HeadParameters) -> Node:
    return params.geometry("head", "tilt_motor_clamp")


def _clamp_screw_dy(params: HeadParameters) -> tuple[float, float]:
    dy = _clamp(params).num("screw_dy", positive=True)
    return -dy, dy


def _clamp_screw_z(params: HeadParameters) -> float:
    motor = params.purchased(params.drive("eyes_tilt").text("motor"))
    tmz = params.geometry("head", "tilt_motor").num("z")
    return tmz - motor.num("diameter") / 2 - _clamp(params).num("screw_below", positive=True)


def _tilt_motor_clamp(params: HeadParameters, inner: float, x_back: float, tmx: float, tmz: float,
                      y_motor: float) -> tuple[Part, list[Part]]:
    """The printed block that holds the tilt motor's body against the back plate's inner face (x_back), and its
    two M3 screws: through a lug under the motor, heads sunk in counterbores from the front, into M3 holes
    tapped through the back plate (geometry.head.tilt_motor_clamp)."""
    c = _clamp(params)
    motor = params.purchased(params.drive("eyes_tilt").text("motor"))
    screw = params.purchased(CLAMP_SCREW)
    z_screw = _clamp_screw_z(params)
    bt = params.geometry("head", "back_plate").num("thickness")
    engagement, counterbore = c.num("screw_engagement", positive=True), c.num("counterbore", positive=True)
    half = c.num("half_width", positive=True)
    if engagement > bt:
        raise ParameterError(f"{params.path}: geometry.head.back_plate.thickness: {bt:g} is less than the "
                             f"{engagement:g} mm the tilt motor clamp's screws reach into it")
    if counterbore <= screw.num("head_diameter"):
        raise ParameterError(f"{params.path}: geometry.head.tilt_motor_clamp.counterbore: {counterbore:g} does not "
                             f"take the {screw.num('head_diameter'):g} mm heads of {CLAMP_SCREW}")
    seat = x_back + screw.num("length") - engagement   # the heads bear here, facing +x
    x_front = tmx + c.num("front", positive=True)
    block = geom.box(x_back, x_front, y_motor - half, y_motor + half,
                     z_screw - counterbore / 2 - c.num("base", positive=True), tmz + c.num("top", positive=True))
    tools = [geom.cyl("y", motor.num("diameter"), y_motor - half - 1, y_motor + half + 1, (tmx, tmz))]
    screws = []
    clearance = mounts.clearance_hole(params, CLAMP_SCREW)
    for i, dy in enumerate(_clamp_screw_dy(params)):
        tools += [geom.cyl("x", clearance, x_back - 1, x_front + 1, (y_motor + dy, z_screw)),
                  geom.cyl("x", counterbore, seat, x_front + 1, (y_motor + dy, z_screw))]
        screws.append(purchased.screw(params, f"tilt_clamp_screw_{i}", CLAMP_SCREW, "head_frame",
                                      loc(seat, y_motor + dy, z_screw, ry=-90)))
    clamp = Part("eyes_tilt_motor_clamp", "eyes_tilt_motor_clamp", "head_frame", "printed",
                 geom.single_solid(geom.cut(block, *tools), "tilt motor clamp"), material="petg-printed",
                 color=PRINTED)
    return clamp, screws


def tilt_clamp_back_holes(params: HeadParameters) -> list[cq.Shape]:
    """The clamp screws' tapped holes through the back plate (head frame), drawn at the thread."""
    h = params.geometry("head")
    x0, bt = h.node("floor").num("x_min"), h.node("back_plate").num("thickness")
    motor = params.purchased(params.drive("eyes_tilt").text("motor"))
    gear = params.purchased(params.drive("eyes_tilt").text("gearhead"))
    inner = h.node("floor").num("half_width") - h.node("side_plate").num("thickness")
    y_motor = inner - gear.num("length") - motor.num("length") / 2
    z_screw = _clamp_screw_z(params)
    d = params.purchased(CLAMP_SCREW).num("diameter")
    return [geom.cyl("x", d, x0 - 1, x0 + bt + 1, (y_motor + dy, z_screw)) for dy in _clamp_screw_dy(params)]
