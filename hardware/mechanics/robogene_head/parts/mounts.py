# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Motor mounts and timing pulleys: small machined parts shared by several joints."""
from __future__ import annotations

import math

import cadquery as cq

from robogene_head_model import drive_limits
from robogene_head_model.params import HeadParameters, Node, ParameterError

from .. import geom
from . import gearhead_screws
from .drive_hubs import LAND_DEPTH

FIXING_SCREW = "iso7380-M3x8"   # what holds a mount plate on the structure


def clearance_hole(params: HeadParameters, screw: str) -> float:
    """Clearance hole for a screw through a part (geometry.clearance_holes, by thread: M2, M3...)."""
    thread = f"M{params.purchased(screw).num('diameter', positive=True):g}"
    hole = params.geometry("clearance_holes").num(thread, positive=True)
    if hole <= params.purchased(screw).num("diameter"):
        raise ParameterError(f"{params.path}: geometry.clearance_holes.{thread}: {hole:g} does not clear an {thread}")
    return hole


def mount(params: HeadParameters, joint: str) -> Node:
    return params.geometry("motor_mounts", joint)


def mount_thickness(params: HeadParameters, joint: str) -> float:
    return mount(params, joint).num("thickness", positive=True)


def mount_fixings(params: HeadParameters, joint: str) -> list[tuple[float, float]]:
    return mount(params, joint).points("fixings")


def mount_slot(params: HeadParameters, joint: str) -> float:
    """How far the plate slides along x on its fixings (0: it does not)."""
    node = mount(params, joint)
    return node.num("slot", minimum=0) if node.has("slot") else 0.0


def mount_outline(params: HeadParameters, joint: str) -> tuple[float, float, float, float]:
    x0, x1, y0, y1 = mount(params, joint).vec("outline", 4)
    if not (x0 < 0 < x1 and y0 < 0 < y1):
        raise ParameterError(f"{params.path}: geometry.motor_mounts.{joint}.outline: expected x0 < 0 < x1 and "
                             f"y0 < 0 < y1 about the gearhead axis, got {[x0, x1, y0, y1]}")
    return x0, x1, y0, y1


def mount_plate(params: HeadParameters, joint: str, outline: tuple[float, float, float, float],
                gearhead_diameter: float, counterbores: bool = True) -> cq.Shape:
    """Flange plate of geometry.motor_mounts.<joint> in z 0..thickness with its axis at the origin, outline (x0, x1,
    y0, y1); the gearhead's flange bears on z = thickness. A pilot hole for the output shaft, the gearhead's four
    M2 screw holes (counterbored from z = 0 unless counterbores is False: gearhead_screws), and M3 clearance holes
    at its fixings for the screws that hold the plate on the structure, drawn as slots along x where it slides."""
    thickness, fixings, slot = mount_thickness(params, joint), mount_fixings(params, joint), mount_slot(params, joint)
    hole = params.geometry("motor_mounts").num("pilot_hole", positive=True)
    clearance = clearance_hole(params, FIXING_SCREW)
    x0, x1, y0, y1 = outline
    plate = geom.box(x0, x1, y0, y1, 0, thickness)
    node = mount(params, joint)
    if node.has("round_top") and node.raw("round_top") is True:
        # beyond the axis the plate keeps within the gearhead's circle, clear of what turns around that axis
        r = gearhead_diameter / 2
        plate = geom.cut(plate, geom.cut(geom.box(0, x1 + 1, y0 - 1, y1 + 1, -1, thickness + 1),
                                         geom.cyl("z", 2 * r, -2, thickness + 2)))
    holes = [geom.cyl("z", hole, -1, thickness + 1),
             *gearhead_screws.holes(params, gearhead_diameter, thickness, counterbores)]
    for x, y in fixings:
        holes.append(geom.cyl("z", clearance, -1, thickness + 1, (x - slot / 2, y)))
        if slot > 0:
            holes.append(geom.cyl("z", clearance, -1, thickness + 1, (x + slot / 2, y)))
            holes.append(geom.box(x - slot / 2, x + slot / 2, y - clearance / 2, y + clearance / 2,
                                  -1, thickness + 1))
    return geom.single_solid(geom.cut(plate, *holes), f"motor_mount_{joint}")


def mount_note(params: HeadParameters, joint: str) -> str:
    """What the plate's drawing says about its holes."""
    clearance, slot = clearance_hole(params, FIXING_SCREW), mount_slot(params, joint)
    if slot > 0:
        return (f"{clearance:g} x {clearance + slot:g} slots along x: M3 into the floor, slide to tension the belt; "
                f"4 x {gearhead_screws.clearance(params):g} on the gearhead's bolt circle")
    return f"{clearance:g} holes: M3 fixing screws. " + gearhead_screws.note(params)


def stage(params: HeadParameters, joint: str) -> Node:
    """geometry.pulleys.<yaw|tilt>: the belt stage of a belted joint (its teeth, belt stock, pitch and width)."""
    from robogene_head_model.drive_limits import BELTED
    if joint not in BELTED:
        raise ParameterError(f"{params.path}: {joint} has no belt stage (belted: {', '.join(BELTED)})")
    return params.geometry("pulleys", BELTED[joint])


def belt_key(params: HeadParameters, joint: str) -> str:
    """The purchased belt stock the joint's stage runs, cut to its tooth count."""
    return stage(params, joint).text("belt")


def belt_pitch(params: HeadParameters, joint: str) -> float:
    """The pitch the joint's pulleys are drawn at (the belt profile's; torque_path checks the two agree)."""
    return stage(params, joint).num("pitch", positive=True)


def pulley_width(params: HeadParameters, joint: str) -> float:
    """The joint's pulleys' width over their flanges."""
    return stage(params, joint).num("width", positive=True)


def pitch_differential(params: HeadParameters) -> float:
    """MXL and XL alike: pitch diameter less the teeth's outside diameter."""
    return params.geometry("pulleys").num("pitch_differential", positive=True)


def rim(params: HeadParameters, joint: str) -> float:
    """How far the stage's pulley flanges stand out beyond the teeth: its own `rim`, else pulleys.flange.rim."""
    node = stage(params, joint)
    return (node if node.has("rim") else params.geometry("pulleys", "flange")).num("rim", positive=True)


def flange_thickness(params: HeadParameters, joint: str) -> float:
    """Each of the stage's pulley flanges, thick: its own `flange_thickness` (a catalogue pulley's), else
    pulleys.flange.thickness."""
    node = stage(params, joint)
    if node.has("flange_thickness"):
        return node.num("flange_thickness", positive=True)
    return params.geometry("pulleys", "flange").num("thickness", positive=True)


def belt_room(params: HeadParameters, joint: str) -> tuple[float, float, float]:
    """(room, between, widest) in mm: the room the stage's widest belt (its stock's width plus its width_tolerance,
    when the stock gives one) leaves between its pulleys' flanges, the flanges' distance apart and that width.
    Refused when the belt does not run between them."""
    key = belt_key(params, joint)
    belt = params.purchased(key)
    width = pulley_width(params, joint)
    widest = belt.num("width", positive=True) + (belt.num("width_tolerance") if belt.has("width_tolerance") else 0.0)
    f = flange_thickness(params, joint)
    between = width - 2 * f
    if widest > between + 1e-9:
        raise ParameterError(f"{params.path}: purchased.{key}: a {widest:g} mm wide belt (at its widest) does not run "
                             f"between the flanges of the {joint} stage's {width:g} mm pulleys ({f:g} thick, "
                             f"{between:g} mm apart)")
    return between - widest, between, widest


def plate_gap(params: HeadParameters) -> float:
    """The pulleys' distance from the floor's underside and the left side plate's outer face."""
    return params.geometry("pulleys").num("plate_gap", positive=True)


def pitch_diameter(params: HeadParameters, joint: str, teeth: int) -> float:
    return teeth * belt_pitch(params, joint) / math.pi


def pulley(params: HeadParameters, joint: str, teeth: int, bore: float) -> cq.Shape:
    """Pulley envelope of the joint's stage, z 0..width: toothed body at its outside diameter between two flanges
    (a set-screw pulley's hub is joint_pulley's)."""
    width = pulley_width(params, joint)
    outside = pitch_diameter(params, joint, teeth) - pitch_differential(params)
    flange, f = outside + 2 * rim(params, joint), flange_thickness(params, joint)
    body = geom.union(geom.cyl("z", flange, 0, f), geom.cyl("z", outside, f, width - f),
                      geom.cyl("z", flange, width - f, width))
    return geom.single_solid(geom.cut(body, geom.cyl("z", bore, -1, width + 1)), f"pulley_{teeth}T")


def joint_hub(params: HeadParameters) -> Node:
    return params.geometry("pulleys", "joint_hub")


def motor_hub(params: HeadParameters, joint: str) -> Node:
    """The set-screw hub of a catalogue motor pulley (geometry.pulleys.<stage>.motor_hub), keyed as joint_hub."""
    return stage(params, joint).node("motor_hub")


def _hub(params: HeadParameters, hub: Node | None) -> Node:
    return joint_hub(params) if hub is None else hub


def joint_hub_length(params: HeadParameters, hub: Node | None = None) -> float:
    return _hub(params, hub).num("length", positive=True)


def joint_set_screw(params: HeadParameters, hub: Node | None = None) -> str:
    """The purchased set screw of a pulley's hub (the joint pulleys' unless `hub` is given); its length is at most
    the hub's wall, so it sits below the hub's surface."""
    node = _hub(params, hub)
    key = node.text("set_screw")
    screw = params.purchased(key)
    if screw.text("kind") != "set_screw":
        raise node.fail("set_screw", f"{key!r} is a {screw.text('kind')}, expected a set_screw")
    wall = node.num("wall", positive=True)
    if screw.num("length", positive=True) > wall:
        raise node.fail("wall", f"{wall:g} is shorter than the {key} set screw ({screw.num('length'):g}), which "
                                 f"would stand out of the hub")
    if screw.num("diameter", positive=True) >= joint_hub_length(params, hub):
        raise node.fail("length", f"{joint_hub_length(params, hub):g} leaves no metal around the {key} set "
                                   f"screw's thread")
    return key


def set_screw_angles(params: HeadParameters, joint: str, hub: Node | None = None) -> list[float]:
    """Where a pulley's set screws sit about its axis (deg from its x axis): a joint pulley's per stage, a motor
    pulley's in its hub."""
    from robogene_head_model.drive_limits import BELTED
    node, key = (joint_hub(params).node("set_screw_angles"), BELTED[joint]) if hub is None else (hub, "set_screw_angles")
    value = node.raw(key)
    if not isinstance(value, list) or not value:
        raise node.fail(key, f"expected a list of angles (deg), got {value!r}")
    return list(node.vec(key, len(value)))


def joint_hub_span(params: HeadParameters, joint: str, outboard: bool, hub: Node | None = None) -> tuple[float, float]:
    """z range of a pulley's hub in the pulley's frame (body z 0..width): below it or beyond it."""
    width, length = pulley_width(params, joint), joint_hub_length(params, hub)
    return (width, width + length) if outboard else (-length, 0.0)


def flat_depth(params: HeadParameters, bore: float, hub: Node | None = None) -> float:
    """How deep the flat is that each set screw bears on (flat_depth): wide enough for the screw's end."""
    node = _hub(params, hub)
    depth = node.num("flat_depth", positive=True)
    screw = params.purchased(joint_set_screw(params, hub)).num("diameter", positive=True)
    if depth >= bore / 2 or 2 * math.sqrt(bore * bore / 4 - (bore / 2 - depth) ** 2) < screw:
        raise node.fail("flat_depth", f"{depth:g} on a {bore:g} mm shaft does not make a flat as wide as the "
                                       f"M{screw:g} set screw")
    return depth


def set_screw_frames(params: HeadParameters, joint: str, bore: float, outboard: bool,
                     hub: Node | None = None) -> list[cq.Location]:
    """Each set screw's frame in its pulley's frame: +z radially in, its end on the shaft's flat under it (so
    its socket end sits the flat's depth below the hub's surface)."""
    z0, z1 = joint_hub_span(params, joint, outboard, hub)
    length = params.purchased(joint_set_screw(params, hub)).num("length", positive=True)
    r = bore / 2 - flat_depth(params, bore, hub) + length
    frames = []
    for angle in set_screw_angles(params, joint, hub):
        a = math.radians(angle)
        frames.append(cq.Location(cq.Vector(r * math.cos(a), r * math.sin(a), (z0 + z1) / 2), cq.Vector(0, 0, 1), angle)
                      * cq.Location(cq.Vector(), cq.Vector(0, 1, 0), -90))
    return frames


def shaft_flats(params: HeadParameters, joint: str, bore: float, outboard: bool,
                hub: Node | None = None) -> list[cq.Shape]:
    """Tools, in the pulley's frame, that cut the flats the set screws bear on into the shaft, along the hub and on
    past its free end by clearances.minimum: the hub's end face then does not stand on the flat's end (the two
    edges on one circle leave the link's fused mesh non-manifold where the yaw pulley's hub stands free of the roll
    stage)."""
    z0, z1 = joint_hub_span(params, joint, outboard, hub)
    run_out = params.geometry("clearances").num("minimum", positive=True)
    z0, z1 = (z0, z1 + run_out) if outboard else (z0 - run_out, z1)
    inner = bore / 2 - flat_depth(params, bore, hub)
    return [geom.box(inner, bore, -bore, bore, z0, z1).moved(cq.Location(cq.Vector(), cq.Vector(0, 0, 1), angle))
            for angle in set_screw_angles(params, joint, hub)]


def joint_pulley(params: HeadParameters, joint: str, teeth: int, bore: float, outboard: bool,
                 hub_node: Node | None = None) -> cq.Shape:
    """A set-screw pulley: the pulley envelope with a hub (joint_hub_span; the joint pulleys' unless hub_node is
    given) carrying tapped radial holes for its set screws, drawn at the thread's size like every tapped hole of
    the head."""
    hub = _hub(params, hub_node)
    z0, z1 = joint_hub_span(params, joint, outboard, hub_node)
    body = geom.union(pulley(params, joint, teeth, bore), geom.cyl("z", bore + 2 * hub.num("wall", positive=True), z0, z1))
    thread = params.purchased(joint_set_screw(params, hub_node)).num("diameter", positive=True)
    holes = [geom.cyl("z", bore, z0 - 1, z1 + 1)]
    # each tapped hole opens on a flat land LAND_DEPTH below the hub's round surface (as on the drive hubs): in the
    # screw's frame x runs along the pulley's axis, y across, z radially in from the socket end
    outer = bore / 2 + hub.num("wall")
    inside = outer - (bore / 2 - flat_depth(params, bore, hub_node)
                      + params.purchased(joint_set_screw(params, hub_node)).num("length"))
    for frame in set_screw_frames(params, joint, bore, outboard, hub_node):
        holes.append(geom.cyl("z", thread, -1, hub.num("wall") + 1).moved(frame))
        if inside >= LAND_DEPTH:
            holes.append(geom.box(-(thread + 1) / 2, (thread + 1) / 2, -outer - 1, outer + 1,
                                  -inside - 1, -inside + LAND_DEPTH).moved(frame))
    return geom.single_solid(geom.cut(body, *holes), f"joint pulley {joint}")


def belt_teeth(params: HeadParameters, joint: str, centre_distance: float, teeth_a: int, teeth_b: int) -> int:
    """Closed belt for the joint's two pulleys: pitch length 2C + pi(D+d)/2 + (D-d)^2/4C, rounded up to whole teeth
    (the motor is slotted to take up the difference)."""
    big, small = (pitch_diameter(params, joint, max(teeth_a, teeth_b)),
                  pitch_diameter(params, joint, min(teeth_a, teeth_b)))
    length = 2 * centre_distance + math.pi * (big + small) / 2 + (big - small) ** 2 / (4 * centre_distance)
    return math.ceil(length / belt_pitch(params, joint) - 1e-9)


def belts(params: HeadParameters) -> list[tuple[str, str, int]]:
    """(catalog key, joint, teeth) of the two timing belts (head_frame.belt_parts places their envelopes)."""
    out = []
    for joint in ("neck_yaw", "eyes_tilt"):
        distance = drive_limits.belt_centre(params, joint)
        node = stage(params, joint)
        teeth = belt_teeth(params, joint, distance, int(node.num("motor_teeth")), int(node.num("joint_teeth")))
        profile = params.purchased(belt_key(params, joint)).text("profile")
        out.append((f"{profile.lower()}-belt-{teeth}T", joint, teeth))
    return out


def belt_loop(params: HeadParameters, joint: str, centre_distance: float, teeth_a: int, teeth_b: int) -> cq.Shape:
    """Envelope of a closed belt around two pulleys, in pulley a's frame with pulley b at (centre_distance, 0): the
    belt's back (thickness less tooth height) wrapped on both pulleys' outside diameters and along the tangent
    spans between them, centred across the pulleys' width (z). The teeth sit in the grooves, inside the pulley
    envelopes, so they are left out. The section comes from the purchased belt stock the joint's stage names."""
    key = belt_key(params, joint)
    belt = params.purchased(key)
    width = pulley_width(params, joint)
    belt_width = belt.num("width", positive=True)
    back = belt.num("thickness", positive=True) - belt.num("tooth_height", positive=True)
    if back <= 0:
        raise ParameterError(f"{params.path}: purchased.{key}: thickness must exceed tooth_height (the belt's back)")
    belt_room(params, joint)
    ra = (pitch_diameter(params, joint, teeth_a) - pitch_differential(params)) / 2
    rb = (pitch_diameter(params, joint, teeth_b) - pitch_differential(params)) / 2
    z0, z1 = (width - belt_width) / 2, (width + belt_width) / 2

    def hull(extra: float, lo: float, hi: float) -> cq.Shape:
        r1, r2 = ra + extra, rb + extra
        s = (r1 - r2) / centre_distance
        c = math.sqrt(1 - s * s)
        quad = [(r1 * s, r1 * c), (centre_distance + r2 * s, r2 * c),
                (centre_distance + r2 * s, -r2 * c), (r1 * s, -r1 * c)]
        span = cq.Workplane("XY").workplane(offset=lo).polyline(quad).close().extrude(hi - lo).val()
        return geom.union(geom.cyl("z", 2 * r1, lo, hi), geom.cyl("z", 2 * r2, lo, hi, (centre_distance, 0)), span)

    return geom.single_solid(geom.cut(hull(back, z0, z1), hull(0.0, z0 - 1, z1 + 1)), f"belt {key}")


def pulley_note(params: HeadParameters, joint: str, teeth: int, bore: float, set_screws: bool = False,
                hub_node: Node | None = None) -> str:
    """What the drawing of a pulley must say: its teeth are not modelled; a set-screw pulley's hub takes set screws
    (kept short: one line on the sheet)."""
    fixing = ""
    profile = params.purchased(belt_key(params, joint)).text("profile")
    if set_screws:
        screw = params.purchased(joint_set_screw(params, hub_node))
        fixing = (f", hub {len(set_screw_angles(params, joint, hub_node))} x M{screw.num('diameter'):g} tapped radial "
                  f"for {joint_set_screw(params, hub_node)} set screws")
    return (f"{profile} pulley, {teeth} teeth, pitch dia. {pitch_diameter(params, joint, teeth):.2f}, bore {bore:g} "
            f"H7{fixing}; teeth not drawn: {profile} profile")
