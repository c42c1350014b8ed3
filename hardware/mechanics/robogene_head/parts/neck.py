# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Neck base (plates, uprights, board bay), pitch stage and roll stage, with their drives."""
from __future__ import annotations

import cadquery as cq

from robogene_head_model.params import HeadParameters, ParameterError

from .. import geom
from . import board_stack, drive_hubs, gearhead_screws, joint_encoders, mounts, purchased, yaw_bearings
from .base import ALUMINIUM, Part, loc

SCREW = "iso7380-M3x12"
# mm a shim ring must hold a retaining ring's lugs off a bearing's turning inner ring: more than a small deep-groove
# bearing's axial play (about 0.1 mm), which lets the inner ring shift towards the ring
LUG_GAP = 0.3
STANDOFF = "standoff-M3x96-FF"
# mm a gearhead shaft's bore runs past the shaft's end: the shaft bottoms on nothing, the gearhead's flange places it
BORE_RUNOUT = 1.0
UPRIGHT_DRIVE_NOTE = ("M3 tapped (tap drill 2.5), drawn at 3.0: 2 x 6 deep in the bottom face, 4 x 8 deep in the outer "
                      "face for the pitch motor mount. The two holes from the top and the front face into the bore are "
                      "the access to the pitch hub's set screws")
UPRIGHT_BEARING_NOTE = ("M3 tapped (tap drill 2.5), drawn at 3.0: 2 x 6 deep in the bottom face. Bearing bore straight "
                        "through, no shoulder: the floating bearing's outer ring slides in it")
PITCH_STAGE_NOTE = ("Rear lug: 2 x M3 tapped through (tap drill 2.5), drawn at 3.0, for the roll motor mount; cross bar: "
                    "2 x 3.4 through at the front for the front lug's screws. Left hub: 2 x M4 tapped (tap drill 3.3), "
                    "drawn at 4.0, from the shaft bore out, for the set screws on the pitch gearhead's shaft")
ROLL_STAGE_NOTE = ("Rear hub: 2 x M4 tapped (tap drill 3.3), drawn at 4.0, from the shaft bore out, for the set screws on "
                   "the roll gearhead's shaft")
FRONT_LUG_NOTE = ("2 x M3 tapped 8 deep (tap drill 2.5) in the bottom face, drawn at 3.0. Bearing bore straight through, "
                  "no shoulder: the floating bearing's outer ring slides in it")


def clamped_seat(params: HeadParameters, joint: str, inner: float, outer: float, axis: str,
                 at: tuple[float, float], spacer: float) -> tuple[list, float, float, float]:
    """Bore of a FIXED bearing's outer ring through a wall from `inner` to `outer` (coordinates along `axis`, either
    order): a shoulder next to the inside, the bearing's seat, a spacer ring `spacer` thick against its outer ring, the
    retaining ring's groove and a land outside it (geometry.bearing_seats). The spacer keeps the retaining ring's lugs,
    which reach in over the bearing's inner ring, off that ring, which turns while the retaining ring stands still.
    Returns the cutting tools and where the bearing, the spacer and the ring start (their inner faces) along the axis."""
    seats = params.geometry("bearing_seats")
    bearing = params.purchased(params.drive(joint).text("bearing"))
    ring = params.purchased(seats.text("bearing_ring"))
    bw, bo = bearing.num("width"), bearing.num("outside")
    if abs(ring.num("bore") - bo) > 1e-9:
        raise ParameterError(f"{params.path}: geometry.bearing_seats.bearing_ring: {seats.text('bearing_ring')} is for a "
                             f"{ring.num('bore'):g} mm bore, the {joint} bearing is {bo:g} outside")
    inner_ring = bearing.num("inner_ring_outside", positive=True)
    lugs = ring.num("lug_inner_diameter", positive=True)
    s = spacer
    if lugs < inner_ring and s < LUG_GAP:
        raise ParameterError(f"{params.path}: the {seats.text('bearing_ring')} ring's lugs reach in to {lugs:g}, over the "
                             f"{joint} bearing's inner ring ({inner_ring:g} across), which turns while they stand still: "
                             f"a spacer ring at least {LUG_GAP:g} thick must keep them off it (this one: {s:g})")
    sign = 1.0 if outer > inner else -1.0
    wall = abs(outer - inner)
    land, m = seats.num("land", positive=True), ring.num("groove_width", positive=True)
    shoulder = wall - bw - s - m - land
    if shoulder < 1.0:
        raise ParameterError(f"{params.path}: the wall holding the {joint} bearing is {wall:g} thick: it needs "
                             f"{bw + s + m + land + 1:g} for the bearing, the spacer, the ring's groove, the land and a "
                             f"1 mm shoulder")
    hole = seats.num("shoulder_hole", positive=True)
    if hole >= bo:
        raise ParameterError(f"{params.path}: geometry.bearing_seats.shoulder_hole: {hole:g} leaves no shoulder for a "
                             f"{bo:g} mm bearing")
    b0 = inner + sign * shoulder
    s0 = b0 + sign * bw
    g0 = s0 + sign * s
    tools = [geom.cyl(axis, hole, inner - sign, b0 + sign * 0.5, at),
             geom.cyl(axis, bo, b0, outer + sign, at),
             geom.cyl(axis, ring.num("groove_diameter"), g0, g0 + sign * m, at)]
    return tools, b0, s0, g0


def floating_seat(params: HeadParameters, joint: str, inner: float, outer: float, axis: str,
                  at: tuple[float, float]) -> tuple[list, float]:
    """Bore of a FLOATING bearing's outer ring through a wall from `inner` to `outer` (coordinates along `axis`, either
    order): one bore of the outer ring's diameter straight through (the sliding fit, fits.housing_standing_ring), no
    shoulder and no ring, so the outer ring moves with the shaft as it grows; the bearing sits in the middle of the wall.
    The inner ring is the tight one, pressed onto its journal against the journal's collar (journal_collar). Returns the
    cutting tool and where the bearing starts (its inner face) along the axis."""
    bearing = params.purchased(params.drive(joint).text("bearing"))
    bw, bo = bearing.num("width", positive=True), bearing.num("outside", positive=True)
    wall = abs(outer - inner)
    if wall < bw:
        raise ParameterError(f"{params.path}: the wall holding the {joint} bearing is {wall:g} thick, under the "
                             f"bearing's {bw:g} mm width")
    sign = 1.0 if outer > inner else -1.0
    return [geom.cyl(axis, bo, inner - sign, outer + sign, at)], inner + sign * (wall - bw) / 2


def journal_collar(params: HeadParameters, joint: str) -> float:
    """The diameter of the shoulder a floating bearing's inner ring is pressed against (geometry.bearing_seats.collar):
    over the journal, within the inner ring's face, so that it turns clear of the seal and the outer ring."""
    bearing = params.purchased(params.drive(joint).text("bearing"))
    collar = params.geometry("bearing_seats").num("collar", positive=True)
    bore, face = bearing.num("bore", positive=True), bearing.num("inner_ring_outside", positive=True)
    if not bore < collar <= face:
        raise ParameterError(f"{params.path}: geometry.bearing_seats.collar: {collar:g} must be over the {joint} "
                             f"bearing's {bore:g} mm bore and within its inner ring's face ({face:g} across)")
    return collar


def bearing_ring(params: HeadParameters) -> str:
    return params.geometry("bearing_seats").text("bearing_ring")


def shaft_hole(params: HeadParameters, joint: str) -> float:
    """A shaft through a wall that carries no bearing (the drive side): its diameter plus the clearance."""
    bore = params.purchased(params.drive(joint).text("bearing")).num("bore", positive=True)
    return bore + 2 * params.geometry("bearing_seats").num("shaft_clearance", positive=True)


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
    bo = bearing.num("outside")
    height = hp + bo / 2 + 5
    # Both uprights in their design frame at +y. The left one carries the drive: the pitch shaft passes through it
    # to the gearhead, whose bearings locate it. The right one, turned half a turn about z, holds the floating bearing.
    y_face = gap / 2 + ut
    block = geom.box(-ul / 2, ul / 2, gap / 2, y_face, 0, height)
    bottom_holes = [geom.cyl("z", 3.0, -1, 6, (sx * ul / 4, y_up)) for sx in (-1, 1)]
    pitch_hub = pitch_hub_of(params, (0.0, hp))
    upright_drive = geom.cut(block, geom.cyl("y", pitch_hub.diameter + 2 * pitch_hub.clearance, gap / 2 - 1, y_face + 1,
                                             (0, hp)),
                             *pitch_hub.access_holes({"x": ul / 2, "z": height}),
                             *bottom_holes,
                             *[geom.cyl("y", 3.0, y_face - 8, y_face + 1, (fx, hp - fy))
                               for fx, fy in mounts.mount_fixings(params, "neck_pitch")])
    seat, b0 = floating_seat(params, "neck_pitch", gap / 2, y_face, "y", (0, hp))
    # the pitch encoder's bracket screws into the right upright's outer face (turned back into the design frame)
    encoder_holes = [t.moved(loc(rz=180)) for t in joint_encoders.face_holes(params, joint_encoders.ends(params)["neck_pitch"])]
    upright_bearing = geom.cut(block, *seat, *bottom_holes, *encoder_holes)

    parts = [
        Part("neck_base_plate", "neck_base_plate", "neck_base", "machined", geom.single_solid(plate, "plate"),
             material="aluminium-6082", color=ALUMINIUM),
        Part("neck_base_flange", "neck_base_flange", "neck_base", "machined", geom.single_solid(flange, "flange"),
             loc(z=z_flange), material="aluminium-6082", color=ALUMINIUM, note=board_stack.FLANGE_NOTE),
        Part("neck_upright_left", "neck_upright_drive", "neck_base", "machined",
             geom.single_solid(upright_drive, "neck_upright_drive"), material="aluminium-6082", color=ALUMINIUM,
             note=UPRIGHT_DRIVE_NOTE),
        Part("neck_upright_right", "neck_upright_bearing", "neck_base", "machined",
             geom.single_solid(upright_bearing, "neck_upright_bearing"), loc(rz=180),
             material="aluminium-6082", color=ALUMINIUM, note=UPRIGHT_BEARING_NOTE),
    ]
    for i, (x, y) in enumerate(corners):
        parts.append(purchased.standoff(params, f"base_standoff_{i}", STANDOFF, "neck_base", loc(x, y, -T - bay)))
        parts.append(purchased.screw(params, f"base_plate_screw_{i}", SCREW, "neck_base", loc(x, y, 0, rx=180)))
        parts.append(purchased.screw(params, f"base_flange_screw_{i}", SCREW, "neck_base", loc(x, y, z_flange)))
    for i, (x, y) in enumerate(upright_screws):
        parts.append(purchased.screw(params, f"upright_screw_{i}", SCREW, "neck_base", loc(x, y, -T)))
    # The floating pitch bearing in the right upright's bore (design +y, turned to -y), its inner ring on the pitch
    # stage's journal (_pitch_stage); the drive is bolted on the left upright.
    y_out = gap / 2 + ut
    parts.append(purchased.bearing(params, "neck_pitch_bearing_right", params.drive("neck_pitch").text("bearing"),
                                   "neck_base", loc(0, -b0, hp, rx=90)))
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
    return parts


def front_lug_x(params: HeadParameters) -> tuple[float, float]:
    """The front lug's inner and outer faces along x, pitch-link frame."""
    g = params.geometry("neck_pitch_stage")
    span = g.node("lug").num("span", positive=True)
    return span / 2, span / 2 + g.node("front_lug").num("thickness", positive=True)


def _pitch_stage(params: HeadParameters) -> list[Part]:
    """Pitch stage in the neck_pitch_link frame (origin on the pitch axis): a one-piece stage with the rear lug, and
    the front lug bolted on its cross bar after the roll stage is in."""
    g = params.geometry("neck_pitch_stage")
    b, lug = g.node("body"), g.node("lug")
    bl, bw, bh = b.num("length", positive=True), b.num("width", positive=True), b.num("height", positive=True)
    lt, lw, span = lug.num("thickness", positive=True), lug.num("width", positive=True), lug.num("span", positive=True)
    up = params.geometry("neck_base", "upright")
    y_out = up.num("gap") / 2 + up.num("thickness")
    zr = params.joints["neck_roll"].origin[2]
    gear = params.purchased(params.drive("neck_pitch").text("gearhead"))
    hub = pitch_hub_of(params, (0.0, 0.0))
    pitch_bore = params.purchased(params.drive("neck_pitch").text("bearing")).num("bore", positive=True)
    pitch_plate = mounts.mount_thickness(params, "neck_pitch")   # the gearhead's flange, so its shaft's reach
    roll_fixings = mounts.mount_fixings(params, "neck_roll")
    x_out = span / 2 + lt
    fx0, fx1 = front_lug_x(params)
    bar = bh / 2 - 4
    lug_screw = params.purchased(SCREW)
    lug_screws = [((fx0 + fx1) / 2, sy * g.node("front_lug").num("screw_dy", positive=True)) for sy in (1, -1)]
    if lug_screw.num("length") - 4 < 6 or any(abs(y) + lug_screw.num("head_diameter") / 2 > lw / 2 for _, y in lug_screws):
        raise ParameterError(f"{params.path}: geometry.neck_pitch_stage.front_lug.screw_dy: the front lug's {SCREW} "
                             f"do not fit its {lw:g} mm width")
    stage = geom.union(
        geom.box(-bl / 2, bl / 2, -bw / 2, bw / 2, -bh / 2, bh / 2),
        geom.box(-x_out, fx1, -lw / 2, lw / 2, bar, bh / 2),                     # cross bar under both lugs
        geom.box(-x_out, -span / 2, -lw / 2, lw / 2, bar, zr + lw / 2),        # rear lug
        geom.cyl("y", hub.diameter, bw / 2 - 1, y_out - hub.clearance),     # the drive's hub, integral with the stage
        geom.cyl("y", pitch_bore, -y_out, -bw / 2 + 1),                      # the floating bearing's journal
        geom.cyl("y", journal_collar(params, "neck_pitch"), -pitch_bearing_at(params), -bw / 2 + 1),  # and its collar
    )
    # The rear lug carries no bearing: the roll gearhead's own bearings are the roll shaft's fixed bearing.
    stage = geom.cut(stage,
                     geom.cyl("y", gear.num("shaft_diameter"), hub.tip - BORE_RUNOUT, y_out + 1),
                     *hub.tapped_holes(), *hub.lands(),
                     geom.cyl("x", shaft_hole(params, "neck_roll"), -x_out - 1, -span / 2 + 1, (0, zr)),
                     *[geom.cyl("x", 3.0, -x_out - 1, -span / 2 + 1, (fy, zr + fx)) for fx, fy in roll_fixings],
                     *[geom.cyl("z", mounts.clearance_hole(params, SCREW), bar - 1, bh / 2 + 1, c) for c in lug_screws],
                     *joint_encoders.shaft_cuts(params, joint_encoders.ends(params)["neck_pitch"]))
    seat, b0 = floating_seat(params, "neck_roll", fx0, fx1, "x", (0, zr))
    front = geom.cut(geom.box(fx0, fx1, -lw / 2, lw / 2, bh / 2, zr + lw / 2), *seat,
                     *[geom.cyl("z", 3.0, bh / 2 - 1, bh / 2 + lug_screw.num("length") - 4, c) for c in lug_screws],
                     *joint_encoders.face_holes(params, joint_encoders.ends(params)["neck_roll"]))   # the roll encoder's bracket
    parts = [Part("neck_pitch_stage", "neck_pitch_stage", "neck_pitch_link", "machined", geom.single_solid(stage, "pitch stage"),
                  material="aluminium-6082", color=ALUMINIUM, note=PITCH_STAGE_NOTE),
             Part("neck_pitch_front_lug", "neck_pitch_front_lug", "neck_pitch_link", "machined",
                  geom.single_solid(front, "front lug"), material="aluminium-6082", color=ALUMINIUM, note=FRONT_LUG_NOTE)]
    for i, (x, y) in enumerate(lug_screws):   # heads under the cross bar, 4 mm of it, the rest into the lug
        parts.append(purchased.screw(params, f"front_lug_screw_{i}", SCREW, "neck_pitch_link", loc(x, y, bar)))
    parts += hub_screws(params, hub, "neck_pitch_link")
    key = params.drive("neck_roll").text("bearing")
    parts.append(purchased.bearing(params, "neck_roll_bearing_front", key, "neck_pitch_link", loc(b0, 0, zr, ry=90)))
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
    return parts


def _roll_stage(params: HeadParameters) -> list[Part]:
    """Roll stage in the neck_roll_link frame (origin on the roll axis), carrying the fixed yaw shaft and pulley."""
    b = params.geometry("neck_roll_stage", "body")
    bl, bw, bh = b.num("length", positive=True), b.num("width", positive=True), b.num("height", positive=True)
    lug = params.geometry("neck_pitch_stage", "lug")
    x_out = lug.num("span") / 2 + lug.num("thickness")
    x_front = front_lug_x(params)[1]
    zy = params.joints["neck_yaw"].origin[2]
    gear = params.purchased(params.drive("neck_roll").text("gearhead"))
    yaw_bearing = params.purchased(params.drive("neck_yaw").text("bearing"))
    shaft = yaw_bearing.num("bore")
    roll_bore = params.purchased(params.drive("neck_roll").text("bearing")).num("bore", positive=True)
    roll_plate = mounts.mount_thickness(params, "neck_roll")   # the gearhead's flange, so its shaft's reach
    tip = -x_out + gear.num("shaft_length") - roll_plate
    hub = drive_hubs.hub(params, "neck_roll", "x", (0.0, 0.0), tip, -1.0)
    x_lug = lug.num("span") / 2
    if -x_lug + hub.clearance >= -bl / 2 or hub.plane - hub.screw_diameter / 2 < -x_lug + hub.clearance + 1:
        raise ParameterError(f"{params.path}: geometry.drive_hubs.neck_roll: the roll hub between the rear lug "
                             f"(x = {-x_lug:g}) and the roll stage's body (x = {-bl / 2:g}) has no room for its set "
                             f"screws at x = {hub.plane:g}")
    stage = geom.union(geom.box(-bl / 2, bl / 2, -bw / 2, bw / 2, -bh / 2, bh / 2),
                       geom.cyl("x", roll_bore, bl / 2 - 1, x_front), geom.cyl("x", roll_bore, -x_out, -bl / 2 + 1),
                       geom.cyl("x", journal_collar(params, "neck_roll"), bl / 2 - 1, roll_bearing_at(params)),  # its collar
                       geom.cyl("x", hub.diameter, -x_lug + hub.clearance, -bl / 2 + 1),      # the drive's hub
                       geom.cyl("z", shaft, bh / 2 - 1, zy + yaw_bearings.shaft_end(params)))
    # The joint pulley's hub hangs below it, onto the roll stage; its set screws bear on flats on the fixed yaw shaft.
    at = loc(z=zy - yaw_pulley_drop(params))
    stage = geom.cut(stage, geom.cyl("x", gear.num("shaft_diameter"), -x_out - 1, tip + BORE_RUNOUT),
                     *hub.tapped_holes(), *hub.lands(), *yaw_bearings.shaft_grooves(params, zy),
                     *[t.moved(at) for t in mounts.shaft_flats(params, "neck_yaw", shaft, outboard=False)],
                     *[t for j in ("neck_roll", "neck_yaw") for t in joint_encoders.shaft_cuts(params, joint_encoders.ends(params)[j])])
    teeth = int(params.geometry("pulleys", "yaw").num("joint_teeth", positive=True))
    screw = mounts.joint_set_screw(params)
    return [
        Part("neck_roll_stage", "neck_roll_stage", "neck_roll_link", "machined", geom.single_solid(stage, "roll stage"),
             material="aluminium-6082", color=ALUMINIUM, note=ROLL_STAGE_NOTE),
        *hub_screws(params, hub, "neck_roll_link"),
        _yaw_joint_pulley(params, teeth, shaft, at),
    ] + [purchased.set_screw(params, f"neck_yaw_pulley_set_screw_{i}", screw, "neck_roll_link", at * frame)
         for i, frame in enumerate(mounts.set_screw_frames(params, "neck_yaw", shaft, outboard=False))] \
        + yaw_bearings.shaft_parts(params, zy)


def _yaw_joint_pulley(params: HeadParameters, teeth: int, shaft: float, at: cq.Location) -> Part:
    """A catalogue pulley where the parameter file lists one for the stage's profile, else made to the drawing."""
    profile = params.purchased(mounts.belt_key(params, "neck_yaw")).text("profile").lower()
    key = f"{profile}-pulley-{teeth}T-bore{shaft:g}"
    shape = mounts.joint_pulley(params, "neck_yaw", teeth, shaft, outboard=False)
    note = mounts.pulley_note(params, "neck_yaw", teeth, shaft, set_screws=True)
    if params.root.node("purchased").has(key):
        return Part("neck_yaw_joint_pulley", key, "neck_roll_link", "purchased", shape, at,
                    mass=params.purchased(key).num("mass"), color=ALUMINIUM, note=note)
    return Part("neck_yaw_joint_pulley", f"pulley_{profile}_{teeth}T_bore{shaft:g}_hub", "neck_roll_link", "machined",
                shape, at, material="aluminium-6082", color=ALUMINIUM, note=note)


def pitch_bearing_at(params: HeadParameters) -> float:
    """|y| of the floating pitch bearing's inner face (towards the stage), where the journal's collar ends."""
    up = params.geometry("neck_base", "upright")
    gap = up.num("gap", positive=True)
    return floating_seat(params, "neck_pitch", gap / 2, gap / 2 + up.num("thickness", positive=True), "y", (0, 0))[1]


def roll_bearing_at(params: HeadParameters) -> float:
    """x of the floating roll bearing's inner face (towards the roll stage), where the front journal's collar ends."""
    fx0, fx1 = front_lug_x(params)
    return floating_seat(params, "neck_roll", fx0, fx1, "x", (0, 0))[1]


def pitch_hub_of(params: HeadParameters, at: tuple[float, float]) -> drive_hubs.Hub:
    """The pitch drive's hub on the pitch stage's left journal; `at`: the pitch axis's (x, z) in the frame wanted."""
    up = params.geometry("neck_base", "upright")
    y_out = up.num("gap") / 2 + up.num("thickness")
    gear = params.purchased(params.drive("neck_pitch").text("gearhead"))
    tip = y_out + mounts.mount_thickness(params, "neck_pitch") - gear.num("shaft_length")
    hub = drive_hubs.hub(params, "neck_pitch", "y", at, tip, 1.0)
    if not (up.num("gap") / 2 < hub.plane - hub.access / 2 and hub.plane + hub.access / 2 < y_out):
        raise ParameterError(f"{params.path}: geometry.drive_hubs.neck_pitch: the set screws at y = {hub.plane:g} "
                             f"must be reached through the left upright ({up.num('gap') / 2:g}..{y_out:g})")
    return hub


def hub_screws(params: HeadParameters, hub: drive_hubs.Hub, link: str) -> list[Part]:
    return [purchased.set_screw(params, f"{hub.joint}_hub_screw_{i}", hub.screw, link, hub.screw_location(d))
            for i, d in enumerate(hub.directions)]


def yaw_pulley_drop(params: HeadParameters) -> float:
    """Depth of the yaw pulleys' lower face below the yaw joint frame: pulleys.plate_gap under the head floor."""
    return (params.geometry("head", "floor").num("thickness") + mounts.plate_gap(params)
            + mounts.pulley_width(params, "neck_yaw"))


def build(params: HeadParameters) -> list[Part]:
    # The yaw pulleys hang between the roll stage and the head floor.
    zy = params.joints["neck_yaw"].origin[2]
    top = params.geometry("neck_roll_stage", "body").num("height") / 2
    if zy - yaw_pulley_drop(params) - top < params.geometry("clearances").num("minimum"):
        raise ParameterError(f"{params.path}: joints.neck_yaw.origin[2]: {zy} leaves no room for the yaw pulleys "
                             f"above the roll stage (top at {top})")
    # The joint pulley's hub stands on the roll stage's top face (both on the roll link): it may reach it, not into it.
    room = zy - yaw_pulley_drop(params) - top
    if mounts.joint_hub_length(params) > room + 1e-9:
        raise ParameterError(f"{params.path}: geometry.pulleys.joint_hub.length: {mounts.joint_hub_length(params):g} "
                             f"reaches into the roll stage: the yaw joint pulley stands {room:g} above it")
    return _base(params) + _pitch_stage(params) + _roll_stage(params)
