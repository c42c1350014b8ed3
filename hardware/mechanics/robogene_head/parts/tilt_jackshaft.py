# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The eye tilt's drive up to its motor pulley: the 16/7 gearhead clamped by its body in a machined housing on the
left side plate's inner face, a clamp coupling from its 3 mm shaft to a 6 mm jackshaft in two bearings of the
housing, and the catalogue 14T XL pulley on the jackshaft outside the plate (geometry.tilt_jackshaft).

Why: the gearhead's 8 mm shaft leaves too little beyond any plate its flange is screwed to for a catalogue
pulley or coupling hub (docs/fabricate.md, "Torque paths"). Along the axis (head frame y), from the side plate's
inner face inwards: the fixed bearing, the land, the floating bearing, the coupling, the clamp bore round the
gearhead's body, which holds it axially too (the belt puts no axial load on it). The fixed bearing's outer ring sits
between the land and the side plate, its inner ring between the shaft's collar and a spacer sleeve out through the plate
to the motor pulley's face; the floating bearing's inner ring is pressed against the collar's other face, its outer ring
slides in a seat that stops `float_room` short of the land (bearing_arrangement)."""
from __future__ import annotations

from dataclasses import dataclass

import cadquery as cq

from robogene_head_model.params import HeadParameters, Node, ParameterError

from .. import geom
from . import mounts, purchased
from .base import ALUMINIUM, Part, loc

JOINT = "eyes_tilt"
HOUSING_NOTE = ("Bearing seats: the fixed bearing's against the land from the side plate's face, the floating one's "
                "from the gearhead's end; M3 tapped in the flange for the fixings; the clamp bore split ahead of the "
                "axis, M3 clearance above the split, tapped below.")


def node(params: HeadParameters) -> Node:
    return params.geometry("tilt_jackshaft")


@dataclass(frozen=True)
class Layout:
    """Where things sit along the tilt motor's axis (head frame y) and about it (x, z)."""
    x: float
    z: float
    inner: float            # the left side plate's inner face
    outer: float            # its outer face
    gearhead_face: float    # the gearhead's output face, `gap` from the coupling
    coupling: tuple[float, float]
    floating: float         # the floating bearing's inboard face
    land: tuple[float, float]
    fixed: float            # the fixed bearing's inboard face
    shaft: tuple[float, float]
    pulley: float           # the motor pulley's inner flange face


def layout(params: HeadParameters) -> Layout:
    n = node(params)
    head = params.geometry("head")
    hw = head.node("floor").num("half_width", positive=True)
    inner = hw - head.node("side_plate").num("thickness", positive=True)
    tm = head.node("tilt_motor")
    bearing = params.purchased(n.text("bearing"))
    width = bearing.num("width", positive=True)
    coupling = params.purchased(n.text("coupling"))
    gap, land = n.num("gap", positive=True), n.num("land", positive=True)
    fixed = inner - width
    floating = fixed - land - width
    c1 = floating - gap
    c0 = c1 - coupling.num("length", positive=True)
    face = c0 - gap
    gear = params.purchased(params.drive(JOINT).text("gearhead"))
    shaft_free = gear.num("shaft_length", positive=True) - (c0 - face)
    if shaft_free < coupling.num("length") / 4:
        raise n._fail("gap", f"leaves {shaft_free:g} mm of the {gear.num('shaft_length'):g} mm gearhead shaft in "
                                  f"the coupling")
    pulley = hw + mounts.plate_gap(params)
    end = pulley + mounts.pulley_width(params, JOINT) + mounts.joint_hub_length(params, mounts.motor_hub(params, JOINT))
    return Layout(tm.num("x"), tm.num("z"), inner, hw, face, (c0, c1), floating, (floating + width, fixed), fixed,
                  ((c0 + c1) / 2 + gap, end), pulley)


def _at(lay: Layout, u: float = 0.0, v: float = 0.0) -> tuple[float, float]:
    """A point of the axis's cross-section (u ahead, v above) as the (x, z) of a cylinder along y."""
    return lay.x + u, lay.z + v


def _bearing_key(params: HeadParameters) -> str:
    key = node(params).text("bearing")
    if params.purchased(key).text("kind") != "bearing":
        raise node(params)._fail("bearing", f"{key!r} is not a bearing")
    return key


def screw_frames(params: HeadParameters) -> dict[str, list[cq.Location]]:
    """Each screw's frame in the head frame (purchased.screw: the head on z = 0, the shank along +z)."""
    n, lay = node(params), layout(params)
    h = n.node("housing")
    coupling = params.purchased(n.text("coupling"))
    c0, c1 = lay.coupling
    off, seat = coupling.num("offset", positive=True), coupling.num("seat", positive=True)
    clamp_u = (params.purchased(params.drive(JOINT).text("gearhead")).num("diameter") / 2 + h.num("lug")) / 2
    return {
        # down through each half of the coupling, ahead of the axis
        "coupling": [loc(lay.x + off, (c0 * 3 + c1) / 4, lay.z + seat, rx=180),
                     loc(lay.x + off, (c0 + c1 * 3) / 4, lay.z + seat, rx=180)],
        # down through the clamp lug, across its split
        "clamp": [loc(lay.x + clamp_u, lay.gearhead_face - h.num("clamp") / 2, lay.z + h.num("half"), rx=180)],
        # from outside through the side plate's slots into the flange
        "fixing": [loc(lay.x + u, lay.outer, lay.z + v, rx=90) for u, v in n.points("fixings")],
    }


def housing(params: HeadParameters) -> cq.Solid:
    n, lay = node(params), layout(params)
    h = n.node("housing")
    half, front, fh = h.num("half", positive=True), h.num("front", positive=True), h.num("flange_half", positive=True)
    clamp, lug, split = h.num("clamp", positive=True), h.num("lug", positive=True), h.num("split", positive=True)
    gear = params.purchased(params.drive(JOINT).text("gearhead"))
    bearing = params.purchased(_bearing_key(params))
    coupling = params.purchased(n.text("coupling"))
    cavity = h.num("cavity", positive=True)
    if cavity <= coupling.num("diameter", positive=True):
        raise h._fail("cavity", f"{cavity:g} does not take the {coupling.num('diameter'):g} mm coupling")
    if 2 * half - cavity < 2 or 2 * half <= gear.num("diameter") + 2:
        raise h._fail("half", f"{half:g} leaves under 1 mm of wall round the cavity or the gearhead")
    y0 = lay.gearhead_face - clamp
    x, z = lay.x, lay.z
    body = geom.union(geom.box(x - half, x + half, y0, lay.inner, z - half, z + half),
                      geom.box(x - half, x + front, lay.inner - h.num("flange", positive=True), lay.inner, z - fh, z + fh),
                      geom.box(x, x + lug, y0, lay.gearhead_face, z - half, z + half))
    c0, c1 = lay.coupling
    land0, land1 = lay.land
    off = coupling.num("offset")
    window = h.num("window", positive=True)
    # the cavity reaches 1 mm over the gearhead's front, so its step stands clear of the coupling's end
    tools = [geom.cyl("y", gear.num("diameter"), y0 - 1, lay.gearhead_face, _at(lay)),
             geom.cyl("y", cavity, lay.gearhead_face - 1, lay.floating, _at(lay)),
             # the floating bearing's seat runs on into the land: its outer ring keeps room to slide towards it
             geom.cyl("y", bearing.num("outside"), lay.floating - 0.01, land0 + _float_room(params), _at(lay)),
             geom.cyl("y", bearing.num("inner_ring_outside") + 1.6, land0 - 1, land1 + 1, _at(lay)),
             geom.cyl("y", bearing.num("outside"), land1, lay.inner + 1, _at(lay)),
             # the window the coupling's screws are reached through
             geom.box(x + off - window / 2, x + off + window / 2, c0, c1, z, z + half + 1),
             # the clamp's split ahead of the axis
             geom.box(x, x + lug + 1, y0 - 1, lay.gearhead_face, z - split / 2, z + split / 2)]
    m3 = params.purchased(n.text("fixing_screw")).num("diameter", positive=True)
    frames = screw_frames(params)
    clamp_screw = params.purchased(n.text("clamp_screw"))
    cx, cy, cz = frames["clamp"][0].toTuple()[0]
    tools += [geom.cyl("z", mounts.clearance_hole(params, n.text("clamp_screw")), z, z + half + 1, (cx, cy)),
              geom.cyl("z", clamp_screw.num("diameter"), z - half - 1, z, (cx, cy))]
    depth = params.purchased(n.text("fixing_screw")).num("length") - (lay.outer - lay.inner)
    for u, v in n.points("fixings"):
        tools.append(geom.cyl("y", m3, lay.inner - depth - 1, lay.inner + 1, _at(lay, u, v)))
    return geom.single_solid(geom.cut(body, *tools), "tilt jackshaft housing")


def _float_room(params: HeadParameters) -> float:
    n = node(params)
    room = n.num("float_room", positive=True)
    if room >= n.num("land"):
        raise n._fail("float_room", f"{room:g} leaves no land of the {n.num('land'):g} for the fixed bearing")
    return room


def spacer(params: HeadParameters) -> cq.Shape:
    """The sleeve from the fixed bearing's inner ring out through the side plate to the motor pulley's inner face: the
    inner ring's outboard stop, the collar's diameter (within the inner ring's face), sliding on the shaft."""
    lay = layout(params)
    s = node(params).node("shaft")
    return geom.tube("y", s.num("collar"), s.num("diameter"), lay.inner, lay.pulley, _at(lay))


def _pulley_frame(lay: Layout) -> cq.Location:
    """The motor pulley's frame: its body along +y from its inner flange face."""
    return loc(lay.x, lay.pulley, lay.z, rx=-90)


def jackshaft(params: HeadParameters) -> cq.Solid:
    n, lay = node(params), layout(params)
    s = n.node("shaft")
    d, collar = s.num("diameter", positive=True), s.num("collar", positive=True)
    bearing = params.purchased(_bearing_key(params))
    if d != bearing.num("bore"):
        raise s._fail("diameter", f"{d:g} is not the {bearing.num('bore'):g} mm bore of {n.text('bearing')}")
    if not d < collar <= bearing.num("inner_ring_outside"):
        raise s._fail("collar", f"{collar:g} must stand above the shaft and bear on the inner rings only (up to "
                                f"{bearing.num('inner_ring_outside'):g})")
    hub = mounts.motor_hub(params, JOINT)
    shape = geom.union(geom.cyl("y", d, lay.shaft[0], lay.shaft[1], _at(lay)),
                       geom.cyl("y", collar, lay.land[0], lay.land[1], _at(lay)))
    flats = [t.moved(_pulley_frame(lay)) for t in mounts.shaft_flats(params, JOINT, d, outboard=True, hub=hub)]
    return geom.single_solid(geom.cut(shape, *flats), "tilt jackshaft")


def coupling_shape(params: HeadParameters) -> cq.Shape:
    """The coupling in its own frame: along +z from 0, the gearhead's half first; its screws run along -y from their
    seats, `offset` to -x of the axis (placed: down from above, ahead of the axis)."""
    key = node(params).text("coupling")
    c = params.purchased(key)
    d, length = c.num("diameter", positive=True), c.num("length", positive=True)
    small, large = c.vec("bores", 2)
    screw = params.purchased(c.text("screw"))
    off, seat = c.num("offset", positive=True), c.num("seat", positive=True)
    if off - screw.num("diameter") / 2 <= large / 2:
        raise c._fail("offset", f"{off:g} puts the M{screw.num('diameter'):g} screw into the {large:g} mm bore")
    body = geom.cyl("z", d, 0, length)
    tools = [geom.cyl("z", small, -1, length / 2), geom.cyl("z", large, length / 2, length + 1)]
    for zc in (length / 4, 3 * length / 4):
        # in this frame the screw runs along -y from its seat at y = seat
        tools += [geom.cyl("y", screw.num("head_diameter") + 0.4, seat, d, (-off, zc)),
                  geom.cyl("y", screw.num("diameter"), seat - screw.num("length"), seat, (-off, zc))]
    return geom.single_solid(geom.cut(body, *tools), key)


def build(params: HeadParameters) -> list[Part]:
    """The housing, jackshaft, bearings, coupling, motor pulley, the tilt drive and their screws (head frame)."""
    n, lay = node(params), layout(params)
    al = dict(material="aluminium-6082", color=ALUMINIUM)
    bearing = _bearing_key(params)
    parts = [Part("eyes_tilt_jackshaft_housing", "eyes_tilt_jackshaft_housing", "head_frame", "machined",
                  housing(params), note=HOUSING_NOTE, **al),
             Part("eyes_tilt_jackshaft", "eyes_tilt_jackshaft", "head_frame", "machined", jackshaft(params),
                  note="Flats 0.5 deep for the motor pulley's set screws; collar between the bearings' inner rings.",
                  turning=True, material="steel", color=ALUMINIUM),
             purchased.bearing(params, "eyes_tilt_jackshaft_bearing_fixed", bearing, "head_frame",
                               loc(lay.x, lay.fixed, lay.z, rx=-90)),
             purchased.bearing(params, "eyes_tilt_jackshaft_bearing_floating", bearing, "head_frame",
                               loc(lay.x, lay.floating, lay.z, rx=-90)),
             Part("eyes_tilt_jackshaft_spacer", "eyes_tilt_jackshaft_spacer", "head_frame", "machined", spacer(params),
                  note="Sleeve, slides on the jackshaft: the fixed bearing's inner ring between it and the collar.",
                  material="steel", color=ALUMINIUM)]
    key = n.text("coupling")
    # the coupling's frame turned half round its axis, then laid along +y: its +y (the screws' side) up, its -x ahead
    parts.append(Part("eyes_tilt_coupling", key, "head_frame", "purchased", coupling_shape(params),
                      loc(lay.x, lay.coupling[0], lay.z, rx=-90) * loc(rz=180),
                      mass=params.purchased(key).num("mass"), color=ALUMINIUM))
    frames = screw_frames(params)
    screw = params.purchased(key).text("screw")
    parts += [purchased.screw(params, f"eyes_tilt_coupling_screw_{i}", screw, "head_frame", f)
              for i, f in enumerate(frames["coupling"])]
    parts.append(purchased.screw(params, "eyes_tilt_clamp_screw", n.text("clamp_screw"), "head_frame", frames["clamp"][0]))
    parts += [purchased.screw(params, f"tilt_housing_screw_{i}", n.text("fixing_screw"), "head_frame", f)
              for i, f in enumerate(frames["fixing"])]
    parts += purchased.drive_stack(params, JOINT, "head_frame", loc(lay.x, lay.gearhead_face, lay.z, rx=90))
    # the catalogue motor pulley, its set-screw hub outboard
    hub = mounts.motor_hub(params, JOINT)
    teeth = int(mounts.stage(params, JOINT).num("motor_teeth", positive=True))
    bore = n.node("shaft").num("diameter")
    pulley_key = f"{params.purchased(mounts.belt_key(params, JOINT)).text('profile').lower()}-pulley-{teeth}T-bore{bore:g}"
    if not params.root.node("purchased").has(pulley_key):
        raise ParameterError(f"{params.path}: purchased: no {pulley_key!r} for the tilt motor pulley")
    at = _pulley_frame(lay)
    parts.append(Part("eyes_tilt_motor_pulley", pulley_key, "head_frame", "purchased",
                      mounts.joint_pulley(params, JOINT, teeth, bore, outboard=True, hub_node=hub), at,
                      mass=params.purchased(pulley_key).num("mass"), color=ALUMINIUM,
                      note=mounts.pulley_note(params, JOINT, teeth, bore, set_screws=True, hub_node=hub)))
    set_screw = mounts.joint_set_screw(params, hub)
    parts += [purchased.set_screw(params, f"eyes_tilt_motor_pulley_set_screw_{i}", set_screw, "head_frame", at * f)
              for i, f in enumerate(mounts.set_screw_frames(params, JOINT, bore, outboard=True, hub=hub))]
    return parts


def side_plate_tools(params: HeadParameters) -> list[cq.Shape]:
    """What the left side plate needs for the stage: the jackshaft's passage and the housing's fixings, slots
    `slot` long along x (the belt's line is within 11 deg of x) so the housing slides to tension the belt."""
    n, lay = node(params), layout(params)
    slot = n.num("slot", minimum=0)
    # the spacer sleeve (the collar's diameter) passes the plate round the shaft
    shaft = n.node("shaft").num("collar") + 2 * params.geometry("bearing_seats").num("shaft_clearance", positive=True)
    m3 = mounts.clearance_hole(params, n.text("fixing_screw"))
    out = []
    for d, (u, v) in [(shaft, (0.0, 0.0)), *[(m3, p) for p in n.points("fixings")]]:
        x, z = _at(lay, u, v)
        out += [geom.cyl("y", d, lay.inner - 1, lay.outer + 1, (x - slot / 2, z)),
                geom.cyl("y", d, lay.inner - 1, lay.outer + 1, (x + slot / 2, z)),
                geom.box(x - slot / 2, x + slot / 2, lay.inner - 1, lay.outer + 1, z - d / 2, z + d / 2)]
    return out
