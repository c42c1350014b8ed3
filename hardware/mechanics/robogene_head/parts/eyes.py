# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Eye-tilt frame, eye cups with their camera mounts, eye-pan drives and the tilt pulley."""
from __future__ import annotations

from robogene_head_model.params import HeadParameters, ParameterError

from .. import geom
from . import cable_shelf, eye_hubs, eye_stops, gearhead_screws, mounts, purchased, tilt_bearings
from .base import ALUMINIUM, PRINTED, Part, loc


def eye_cup(params: HeadParameters):
    """Printed eye cup about the eye centre: a sphere cut flat in front, with a pocket that holds the
    camera board, a lens window and, below, the pocket of the hub that carries it on the pan shaft (eye_hubs). The pocket is open to the back: the board slides
    in from behind against the pocket's front wall, its lens through the window, its flat cable out the back."""
    e = params.geometry("eyes")
    r, front = e.num("cup_radius", positive=True), e.num("cup_front_cut", positive=True)
    cam = params.purchased(params.root.node("cameras").text("model"))
    w, h, t = cam.num("board_width"), cam.num("board_height"), cam.num("thickness")
    # the cup first: what sits in it (the board, the hub below it) is placed from its radius
    corner = ((w / 2) ** 2 + (h / 2) ** 2 + t ** 2) ** 0.5
    if corner > r - 1:
        raise ParameterError(f"{params.path}: geometry.eyes.cup_radius: {r} leaves under 1 mm of wall around the "
                             f"camera board corners (they reach {corner:.1f} mm)")
    # Poles on x, both cut flat: the front face carries the lens, the back face is the print bed side.
    back = r - 1.5
    cup = geom.cut(geom.sphere(r, poles="x"), geom.box(front, r + 1, -r - 1, r + 1, -r - 1, r + 1),
                   geom.box(-r - 1, -back, -r - 1, r + 1, -r - 1, r + 1))
    cup = geom.cut(cup,
                   geom.box(-r - 1, 0, -w / 2, w / 2, -h / 2, h / 2),              # board pocket, open behind
                   geom.cyl("x", cam.num("lens_diameter"), -0.5, front + 1),       # lens window
                   *eye_hubs.cup_cuts(params, -r - e.num("gap", positive=True), r))
    floor = eye_hubs.levels(params, -r - e.num("gap", positive=True))[2]
    if floor > -h / 2 - 1:
        raise ParameterError(f"{params.path}: geometry.eyes.hub.head_height: the hub's head reaches z = {floor:g}, "
                             f"under 1 mm below the camera pocket (z = {-h / 2:g})")
    # the hard-stop lug at its back (eye_stops), hanging towards the tilt frame's plate
    cup = geom.union(cup, eye_stops.lug(params, -r - e.num("gap", positive=True)))
    return geom.single_solid(cup, "eye cup")


def build(params: HeadParameters) -> list[Part]:
    e = params.geometry("eyes")
    tf = e.node("tilt_frame")
    r, gap = e.num("cup_radius", positive=True), e.num("gap", positive=True)
    pt, at = tf.num("plate_thickness", positive=True), tf.num("arm_thickness", positive=True)
    ah, al_ = tf.num("arm_height", positive=True), tf.num("arm_length", positive=True)
    half = params.baseline / 2
    head = params.geometry("head")
    inner = head.node("floor").num("half_width") - head.node("side_plate").num("thickness")
    side_gap = params.geometry("clearances").num("minimum")
    arm_out = inner - max(side_gap, 1.0)
    arm_in = arm_out - at
    if arm_in < half + r + gap:
        raise ParameterError(f"{params.path}: geometry.head.floor.half_width: tilt frame arms at |y| >= {arm_in:.1f} "
                             f"would touch the eye cups (they reach {half + r:.1f} + gap {gap})")
    z_top = -r - gap
    pan_gear = params.purchased(params.drive("left_eye_pan").text("gearhead"))
    tilt_bearing = params.purchased(params.drive("eyes_tilt").text("bearing"))
    hw = head.node("floor").num("half_width")
    pw = mounts.pulley_width(params, "eyes_tilt")
    pulley_gap = mounts.plate_gap(params)

    frame = geom.union(
        geom.box(-al_ / 2 - 4, al_ / 2 + 4, -arm_out, arm_out, z_top - pt, z_top),      # plate under the eyes
        geom.box(-al_ / 2, al_ / 2, arm_in, arm_out, z_top - pt, ah),                  # arms up to the tilt axis
        geom.box(-al_ / 2, al_ / 2, -arm_out, -arm_in, z_top - pt, ah),
        geom.cyl("y", tilt_bearing.num("bore"), arm_out - 1,                         # tilt shafts, the left one
                 hw + pulley_gap + pw + mounts.joint_hub_length(params)),             # through the pulley's hub
        # the right journal (out beyond its boss for the joint encoder's magnet holder), the collars against both
        # inner rings
        *tilt_bearings.frame_features(params)[0],
    )
    # The pan gearheads' flanges bear on the plate's underside; their screws come from above, heads sunk below
    # the eye cups.
    flanges = {s: loc(0, s * half, z_top, rx=180) for s in (1, -1)}
    shelf = cable_shelf.shelf(params, -al_ / 2 - 4, z_top - pt, z_top, arm_in)
    stop_pins, stop_holes = [], []
    for side, sign in (("left", 1), ("right", -1)):
        found = eye_stops.pins(params, f"{side}_eye_pan", sign * half, z_top, "eyes_tilt_link")
        stop_pins += found[0]
        stop_holes += found[1]
    pulley_at = loc(0, hw + pulley_gap, 0, rx=-90)   # the tilt joint pulley's frame: its body along +y
    frame = geom.cut(frame, *[geom.cyl("z", pan_gear.num("shaft_diameter") + 2, z_top - pt - 1, z_top + 1, (0, s * half))
                              for s in (1, -1)],
                     *[t.moved(f) for f in flanges.values()
                       for t in gearhead_screws.holes(params, pan_gear.num("diameter"), pt)],
                     *stop_holes, *tilt_bearings.frame_features(params)[1], *cable_shelf.plate_holes(params, shelf),
                     # flats for the joint pulley's set screws on the left tilt shaft, along the pulley's hub
                     *[t.moved(pulley_at) for t in mounts.shaft_flats(params, "eyes_tilt", tilt_bearing.num("bore"),
                                                                      outboard=True)])
    parts = [Part("eyes_tilt_frame", "eyes_tilt_frame", "eyes_tilt_link", "machined", geom.single_solid(frame, "tilt frame"),
                  material="aluminium-6082", color=ALUMINIUM,
                  note="Pan gearheads: " + gearhead_screws.note(params) + " " + eye_stops.PIN_NOTE)] + stop_pins
    parts += [p for p in tilt_bearings.right_parts(params) if p.link == "eyes_tilt_link"]   # the clip on the journal
    parts += cable_shelf.parts(params, shelf)
    teeth = int(params.geometry("pulleys", "tilt").num("joint_teeth", positive=True))
    bore = tilt_bearing.num("bore")
    # The joint pulley's hub stands outboard of it; its set screws bear on the flats of the left tilt shaft.
    at = pulley_at
    # a catalogue pulley where the parameter file lists one for the stage's profile, else made to the drawing
    profile = params.purchased(mounts.belt_key(params, "eyes_tilt")).text("profile").lower()
    key = f"{profile}-pulley-{teeth}T-bore{bore:g}"
    shape = mounts.joint_pulley(params, "eyes_tilt", teeth, bore, outboard=True)
    note = mounts.pulley_note(params, "eyes_tilt", teeth, bore, set_screws=True)
    if params.root.node("purchased").has(key):
        parts.append(Part("eyes_tilt_joint_pulley", key, "eyes_tilt_link", "purchased", shape, at,
                          mass=params.purchased(key).num("mass"), color=ALUMINIUM, note=note))
    else:
        parts.append(Part("eyes_tilt_joint_pulley", f"pulley_{profile}_{teeth}T_bore{bore:g}_hub", "eyes_tilt_link",
                          "machined", shape, at, material="aluminium-6082", color=ALUMINIUM, note=note))
    screw = mounts.joint_set_screw(params)
    parts += [purchased.set_screw(params, f"eyes_tilt_pulley_set_screw_{i}", screw, "eyes_tilt_link", at * frame)
              for i, frame in enumerate(mounts.set_screw_frames(params, "eyes_tilt", bore, outboard=True))]
    cup = eye_cup(params)
    cam_key = params.root.node("cameras").text("model")
    for side, sign in (("left", 1), ("right", -1)):
        joint = f"{side}_eye_pan"
        # The pan gearhead hangs under the tilt plate, output shaft up into the eye cup.
        parts += purchased.drive_stack(params, joint, "eyes_tilt_link", loc(0, sign * half, z_top - pt, rx=180))
        parts += gearhead_screws.screws(params, joint, "eyes_tilt_link", flanges[sign], pan_gear.num("diameter"), pt)
        link = params.joints[joint].child
        parts.append(Part(f"{side}_eye_cup", "eye_cup", link, "printed", cup, material="petg-printed", color=PRINTED))
        parts += eye_hubs.parts(params, side, link, z_top)
        parts.append(purchased.camera(params, f"{side}_camera", cam_key, link, loc()))
    return parts
