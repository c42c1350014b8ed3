# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""A jackshaft stage, for every joint whose gearhead shaft is too short for a catalogue pulley beyond the plate it
would be screwed to: the gearhead clamped by its body in a machined housing on the plate's inner face, a clamp coupling
from its shaft to a jackshaft in two bearings of the housing, and a catalogue set-screw pulley on the jackshaft beyond
the plate (docs/fabricate.md, "Torque paths"). Each joint that has one names its parameters (geometry.<key>) and its
plate in a Stage (parts/tilt_jackshaft.py: the eye tilt's, on the left side plate).

The stage frame: the jackshaft's axis along +y from the gearhead towards the pulley, at (x, z); the plate between
y = inner and y = outer; across the axis u runs ahead (+x) and v above (+z). `placement` takes the stage frame into
the link frame (None: they are the same). Along the axis, from the plate's inner face inwards: the fixed bearing,
the land, the floating bearing, the coupling, the clamp bore round the gearhead's body, which holds it axially too
(the belt puts no axial load on it). The fixed bearing's outer ring sits between the land and the plate, its inner ring
between the shaft's collar and a spacer sleeve out through the plate to the motor pulley's face; the floating
bearing's inner ring is pressed against the collar's other face, its outer ring slides in a seat that stops
`float_room` short of the land (bearing_arrangement)."""
from __future__ import annotations

from dataclasses import dataclass

import cadquery as cq

from robogene_head_model.drive_limits import BELTED
from robogene_head_model.params import HeadParameters, Node, ParameterError

from .. import geom
from . import mounts, purchased
from .base import ALUMINIUM, Part, loc

HOUSING_NOTE = ("Bearing seats: the fixed bearing's against the land from the {plate}'s face, the floating one's "
                "from the gearhead's end; M3 tapped in the flange for the fixings; the clamp bore split ahead of the "
                "axis, M3 clearance above the split, tapped below.")


@dataclass(frozen=True)
class Stage:
    """One joint's jackshaft stage: its parameters, the plate it stands on and where its frame sits in its link."""
    joint: str                       # the drive's joint (eyes_tilt, neck_yaw)
    key: str                         # geometry.<key>: its parameters
    link: str
    x: float                         # the axis in the stage frame
    z: float
    inner: float                     # the plate's faces along the axis: the housing's side, the pulley's side
    outer: float
    plate: str                       # what the plate is, for the drawings' notes
    placement: cq.Location | None = None

    @property
    def short(self) -> str:
        """The stage's belt entry (geometry.pulleys.<short>): the housing screws' names."""
        return BELTED[self.joint]


COUPLING_NOTE = ("One-piece clamp coupling: each half split through one wall on the axis's plane, the relief cut at "
                 "mid-length from the split's side past the axis; the clamp screws' clearance holes above the split, "
                 "tapped through below it. Bores reamed to their fit; screws tightened to 0.6 N m.")


def node(params: HeadParameters, stage: Stage) -> Node:
    return params.geometry(stage.key)


def coupling_made(params: HeadParameters, stage: Stage) -> bool:
    """True: the stage's coupling is made here from its own parameters; False: a catalogue key names it."""
    return isinstance(node(params, stage).raw("coupling"), dict)


def coupling(params: HeadParameters, stage: Stage) -> Node:
    """The coupling's outline, bores and screws: the made coupling's parameters or the purchased one's entry."""
    n = node(params, stage)
    if coupling_made(params, stage):
        return n.node("coupling")
    entry = params.purchased(n.text("coupling"))
    if entry.text("kind") != "coupling":
        raise n.fail("coupling", f"{n.text('coupling')!r} is a {entry.text('kind')}, expected a coupling")
    return entry


def coupling_design(params: HeadParameters, stage: Stage) -> str:
    """The made coupling's design (its STEP file and drawing), or the catalogue key of a purchased one."""
    return f"{stage.joint}_coupling" if coupling_made(params, stage) else node(params, stage).text("coupling")


def placed(stage: Stage, shape: cq.Shape) -> cq.Shape:
    """A shape of the stage frame in the link frame."""
    return shape if stage.placement is None else shape.moved(stage.placement)


def _in_link(stage: Stage, at: cq.Location = None) -> cq.Location:
    at = cq.Location() if at is None else at
    return at if stage.placement is None else stage.placement * at


@dataclass(frozen=True)
class Layout:
    """Where things sit along the jackshaft's axis (stage frame y) and about it (x, z)."""
    x: float
    z: float
    inner: float            # the plate's inner face
    outer: float            # its outer face
    gearhead_face: float    # the gearhead's output face, `gap` from the coupling
    coupling: tuple[float, float]
    floating: float         # the floating bearing's inboard face
    land: tuple[float, float]
    fixed: float            # the fixed bearing's inboard face
    shaft: tuple[float, float]
    pulley: float           # the motor pulley's inner flange face


def layout(params: HeadParameters, stage: Stage) -> Layout:
    n = node(params, stage)
    bearing = params.purchased(n.text("bearing"))
    width = bearing.num("width", positive=True)
    c = coupling(params, stage)
    gap, land = n.num("gap", positive=True), n.num("land", positive=True)
    fixed = stage.inner - width
    floating = fixed - land - width
    c1 = floating - gap
    c0 = c1 - c.num("length", positive=True)
    face = c0 - gap
    gear = params.purchased(params.drive(stage.joint).text("gearhead"))
    shaft_free = gear.num("shaft_length", positive=True) - (c0 - face)
    if shaft_free < c.num("length") / 4:
        raise n.fail("gap", f"leaves {shaft_free:g} mm of the {gear.num('shaft_length'):g} mm gearhead shaft in "
                                  f"the coupling")
    pulley = stage.outer + mounts.plate_gap(params)
    hub = mounts.motor_hub(params, stage.joint)
    end = pulley + mounts.pulley_width(params, stage.joint) + mounts.joint_hub_length(params, hub)
    return Layout(stage.x, stage.z, stage.inner, stage.outer, face, (c0, c1), floating, (floating + width, fixed),
                  fixed, ((c0 + c1) / 2 + gap, end), pulley)


def _at(lay: Layout, u: float = 0.0, v: float = 0.0) -> tuple[float, float]:
    """A point of the axis's cross-section (u ahead, v above) as the (x, z) of a cylinder along y."""
    return lay.x + u, lay.z + v


def bearing_key(params: HeadParameters, stage: Stage) -> str:
    n = node(params, stage)
    key = n.text("bearing")
    if params.purchased(key).text("kind") != "bearing":
        raise n.fail("bearing", f"{key!r} is not a bearing")
    return key


def screw_frames(params: HeadParameters, stage: Stage) -> dict[str, list[cq.Location]]:
    """Each screw's frame in the stage frame (purchased.screw: the head on z = 0, the shank along +z)."""
    n, lay = node(params, stage), layout(params, stage)
    h = n.node("housing")
    c = coupling(params, stage)
    c0, c1 = lay.coupling
    off, seat = c.num("offset", positive=True), c.num("seat", positive=True)
    clamp_u = (params.purchased(params.drive(stage.joint).text("gearhead")).num("diameter") / 2 + h.num("lug")) / 2
    return {
        # down through each half of the coupling, ahead of the axis
        "coupling": [loc(lay.x + off, (c0 * 3 + c1) / 4, lay.z + seat, rx=180),
                     loc(lay.x + off, (c0 + c1 * 3) / 4, lay.z + seat, rx=180)],
        # down through the clamp lug, across its split
        "clamp": [loc(lay.x + clamp_u, lay.gearhead_face - h.num("clamp") / 2, lay.z + h.num("half"), rx=180)],
        # from outside through the plate's slots into the flange
        "fixing": [loc(lay.x + u, lay.outer, lay.z + v, rx=90) for u, v in n.points("fixings")],
    }


def housing(params: HeadParameters, stage: Stage) -> cq.Solid:
    """The housing in the stage frame."""
    n, lay = node(params, stage), layout(params, stage)
    h = n.node("housing")
    half, front, fh = h.num("half", positive=True), h.num("front", positive=True), h.num("flange_half", positive=True)
    # how far the flange reaches behind the axis: up to the body's back (the tilt's) or less, where something
    # stands behind the housing (the yaw's, flanged ahead of the axis only)
    back = h.num("flange_back", minimum=0)
    if back > half:
        raise h.fail("flange_back", f"{back:g} reaches behind the body's back ({half:g} behind the axis)")
    clamp, lug, split = h.num("clamp", positive=True), h.num("lug", positive=True), h.num("split", positive=True)
    gear = params.purchased(params.drive(stage.joint).text("gearhead"))
    bearing = params.purchased(bearing_key(params, stage))
    c = coupling(params, stage)
    cavity = h.num("cavity", positive=True)
    if cavity <= c.num("diameter", positive=True):
        raise h.fail("cavity", f"{cavity:g} does not take the {c.num('diameter'):g} mm coupling")
    if 2 * half - cavity < 2 or 2 * half <= gear.num("diameter") + 2:
        raise h.fail("half", f"{half:g} leaves under 1 mm of wall round the cavity or the gearhead")
    y0 = lay.gearhead_face - clamp
    x, z = lay.x, lay.z
    body = geom.union(geom.box(x - half, x + half, y0, lay.inner, z - half, z + half),
                      geom.box(x - back, x + front, lay.inner - h.num("flange", positive=True), lay.inner, z - fh, z + fh),
                      geom.box(x, x + lug, y0, lay.gearhead_face, z - half, z + half))
    c0, c1 = lay.coupling
    land0, land1 = lay.land
    off = c.num("offset")
    window = h.num("window", positive=True)
    # the cavity reaches 1 mm over the gearhead's front, so its step stands clear of the coupling's end
    tools = [geom.cyl("y", gear.num("diameter"), y0 - 1, lay.gearhead_face, _at(lay)),
             geom.cyl("y", cavity, lay.gearhead_face - 1, lay.floating, _at(lay)),
             # the floating bearing's seat runs on into the land: its outer ring keeps room to slide towards it
             geom.cyl("y", bearing.num("outside"), lay.floating - 0.01, land0 + _float_room(params, stage), _at(lay)),
             geom.cyl("y", bearing.num("inner_ring_outside") + 1.6, land0 - 1, land1 + 1, _at(lay)),
             geom.cyl("y", bearing.num("outside"), land1, lay.inner + 1, _at(lay)),
             # the window the coupling's screws are reached through
             geom.box(x + off - window / 2, x + off + window / 2, c0, c1, z, z + half + 1),
             # the clamp's split ahead of the axis
             geom.box(x, x + lug + 1, y0 - 1, lay.gearhead_face, z - split / 2, z + split / 2)]
    m3 = params.purchased(n.text("fixing_screw")).num("diameter", positive=True)
    frames = screw_frames(params, stage)
    clamp_screw = params.purchased(n.text("clamp_screw"))
    cx, cy, cz = frames["clamp"][0].toTuple()[0]
    tools += [geom.cyl("z", mounts.clearance_hole(params, n.text("clamp_screw")), z, z + half + 1, (cx, cy)),
              geom.cyl("z", clamp_screw.num("diameter"), z - half - 1, z, (cx, cy))]
    depth = params.purchased(n.text("fixing_screw")).num("length") - (lay.outer - lay.inner)
    for u, v in n.points("fixings"):
        tools.append(geom.cyl("y", m3, lay.inner - depth - 1, lay.inner + 1, _at(lay, u, v)))
    return geom.single_solid(geom.cut(body, *tools), f"{stage.joint} jackshaft housing")


def _float_room(params: HeadParameters, stage: Stage) -> float:
    n = node(params, stage)
    room = n.num("float_room", positive=True)
    if room >= n.num("land"):
        raise n.fail("float_room", f"{room:g} leaves no land of the {n.num('land'):g} for the fixed bearing")
    return room


def spacer(params: HeadParameters, stage: Stage) -> cq.Shape:
    """The sleeve from the fixed bearing's inner ring out through the plate to the motor pulley's inner face (stage
    frame): the inner ring's outboard stop, the collar's diameter (within the inner ring's face), sliding on the
    shaft."""
    lay = layout(params, stage)
    s = node(params, stage).node("shaft")
    return geom.tube("y", s.num("collar"), s.num("diameter"), lay.inner, lay.pulley, _at(lay))


def _pulley_frame(lay: Layout) -> cq.Location:
    """The motor pulley's frame in the stage frame: its body along +y from its inner flange face."""
    return loc(lay.x, lay.pulley, lay.z, rx=-90)


def jackshaft(params: HeadParameters, stage: Stage) -> cq.Solid:
    """The jackshaft in the stage frame."""
    n, lay = node(params, stage), layout(params, stage)
    s = n.node("shaft")
    d, collar = s.num("diameter", positive=True), s.num("collar", positive=True)
    bearing = params.purchased(bearing_key(params, stage))
    if d != bearing.num("bore"):
        raise s.fail("diameter", f"{d:g} is not the {bearing.num('bore'):g} mm bore of {n.text('bearing')}")
    if not d < collar <= bearing.num("inner_ring_outside"):
        raise s.fail("collar", f"{collar:g} must stand above the shaft and bear on the inner rings only (up to "
                                f"{bearing.num('inner_ring_outside'):g})")
    hub = mounts.motor_hub(params, stage.joint)
    shape = geom.union(geom.cyl("y", d, lay.shaft[0], lay.shaft[1], _at(lay)),
                       geom.cyl("y", collar, lay.land[0], lay.land[1], _at(lay)))
    flats = [t.moved(_pulley_frame(lay)) for t in mounts.shaft_flats(params, stage.joint, d, outboard=True, hub=hub)]
    return geom.single_solid(geom.cut(shape, *flats), f"{stage.joint} jackshaft")


def coupling_shape(params: HeadParameters, stage: Stage) -> cq.Shape:
    """The coupling in its own frame: along +z from 0, the gearhead's half first; its screws run along -y from their
    seats, `offset` to -x of the axis (placed: down from above, ahead of the axis). A made coupling is drawn as it is
    machined: each half split on the plane y = 0 through its -x wall, the screw's clearance hole above the split and its
    thread below, and the relief cut at mid-length; a purchased one as its outline, bores and screw holes."""
    c = coupling(params, stage)
    made = coupling_made(params, stage)
    d, length = c.num("diameter", positive=True), c.num("length", positive=True)
    small, large = c.vec("bores", 2)
    if not 0 < small <= large < d:
        raise c.fail("bores", f"expected the gearhead's bore, then the jackshaft's, both under the {d:g} mm outline")
    screw = params.purchased(c.text("screw"))
    sd = screw.num("diameter")
    off, seat = c.num("offset", positive=True), c.num("seat", positive=True)
    if off - sd / 2 <= large / 2:
        raise c.fail("offset", f"{off:g} puts the M{sd:g} screw into the {large:g} mm bore")
    body = geom.cyl("z", d, 0, length)
    tools = [geom.cyl("z", small, -1, length / 2), geom.cyl("z", large, length / 2, length + 1)]
    for zc in (length / 4, 3 * length / 4):
        # in this frame the screw runs along -y from its seat at y = seat
        tools.append(geom.cyl("y", screw.num("head_diameter") + 0.4, seat, d, (-off, zc)))
        if not made:
            tools.append(geom.cyl("y", sd, seat - screw.num("length"), seat, (-off, zc)))
    if not made:
        return geom.single_solid(geom.cut(body, *tools), coupling_design(params, stage))
    split, relief = c.num("split", positive=True), c.num("relief", positive=True)
    depth = c.num("relief_depth", minimum=0)
    if split >= seat:
        raise c.fail("split", f"{split:g} reaches the screw head's seat {seat:g} above the axis")
    if depth > d / 2 - 2:
        raise c.fail("relief_depth", f"{depth:g} leaves under 2 mm of the {d:g} mm coupling joining its halves")
    tip = seat - screw.num("length")
    if tip > -split / 2 - 2 * sd:
        raise c.fail("screw", f"{c.text('screw')} reaches {-split / 2 - tip:.2g} mm into the thread beyond the split, "
                              f"under the {2 * sd:g} mm (2 x its diameter) an aluminium thread needs")
    out = d / 2 + 1
    for zc in (length / 4, 3 * length / 4):
        tools += [geom.cyl("y", mounts.clearance_hole(params, c.text("screw")), split / 2, seat, (-off, zc)),
                  geom.cyl("y", sd, -out, -split / 2, (-off, zc))]
    tools += [geom.box(-out, 0, -split / 2, split / 2, -1, length + 1),
              geom.box(-out, depth, -out, out, length / 2 - relief / 2, length / 2 + relief / 2)]
    return geom.single_solid(geom.cut(body, *tools), coupling_design(params, stage))


def motor_pulley_key(params: HeadParameters, stage: Stage) -> str:
    """The catalogue pulley on the jackshaft: purchased.<profile>-pulley-<teeth>T-bore<shaft>."""
    teeth = int(mounts.stage(params, stage.joint).num("motor_teeth", positive=True))
    bore = node(params, stage).node("shaft").num("diameter")
    profile = params.purchased(mounts.belt_key(params, stage.joint)).text("profile")
    key = f"{profile.lower()}-pulley-{teeth}T-bore{bore:g}"
    if not params.root.node("purchased").has(key):
        raise ParameterError(f"{params.path}: purchased: no {key!r} for the {stage.joint} motor pulley")
    return key


def build(params: HeadParameters, stage: Stage) -> list[Part]:
    """The housing, jackshaft, bearings, coupling, motor pulley, the drive and their screws (link frame)."""
    n, lay = node(params, stage), layout(params, stage)
    j, link = stage.joint, stage.link
    al = dict(material="aluminium-6082", color=ALUMINIUM)
    bearing = bearing_key(params, stage)
    parts = [Part(f"{j}_jackshaft_housing", f"{j}_jackshaft_housing", link, "machined", housing(params, stage),
                  _in_link(stage), note=HOUSING_NOTE.format(plate=stage.plate), **al),
             Part(f"{j}_jackshaft", f"{j}_jackshaft", link, "machined", jackshaft(params, stage), _in_link(stage),
                  note="Flats 0.5 deep for the motor pulley's set screws; collar between the bearings' inner rings.",
                  turning=True, material="steel", color=ALUMINIUM),
             purchased.bearing(params, f"{j}_jackshaft_bearing_fixed", bearing, link,
                               _in_link(stage, loc(lay.x, lay.fixed, lay.z, rx=-90))),
             purchased.bearing(params, f"{j}_jackshaft_bearing_floating", bearing, link,
                               _in_link(stage, loc(lay.x, lay.floating, lay.z, rx=-90))),
             Part(f"{j}_jackshaft_spacer", f"{j}_jackshaft_spacer", link, "machined", spacer(params, stage),
                  _in_link(stage), note="Sleeve, slides on the jackshaft: the fixed bearing's inner ring between it "
                  "and the collar.", material="steel", color=ALUMINIUM)]
    # the coupling's frame turned half round its axis, then laid along +y: its +y (the screws' side) up, its -x ahead
    at = _in_link(stage, loc(lay.x, lay.coupling[0], lay.z, rx=-90) * loc(rz=180))
    design = coupling_design(params, stage)
    if coupling_made(params, stage):
        parts.append(Part(f"{j}_coupling", design, link, "machined", coupling_shape(params, stage), at,
                          note=COUPLING_NOTE, clamp_bores=tuple(coupling(params, stage).vec("bores", 2)), **al))
    else:
        parts.append(Part(f"{j}_coupling", design, link, "purchased", coupling_shape(params, stage), at,
                          mass=params.purchased(design).num("mass"), color=ALUMINIUM))
    frames = screw_frames(params, stage)
    screw = coupling(params, stage).text("screw")
    parts += [purchased.screw(params, f"{j}_coupling_screw_{i}", screw, link, _in_link(stage, f))
              for i, f in enumerate(frames["coupling"])]
    parts.append(purchased.screw(params, f"{j}_clamp_screw", n.text("clamp_screw"), link,
                                 _in_link(stage, frames["clamp"][0])))
    parts += [purchased.screw(params, f"{stage.short}_housing_screw_{i}", n.text("fixing_screw"), link,
                              _in_link(stage, f))
              for i, f in enumerate(frames["fixing"])]
    parts += purchased.drive_stack(params, j, link, _in_link(stage, loc(lay.x, lay.gearhead_face, lay.z, rx=90)))
    # the catalogue motor pulley, its set-screw hub outboard
    hub = mounts.motor_hub(params, j)
    teeth = int(mounts.stage(params, j).num("motor_teeth", positive=True))
    bore = n.node("shaft").num("diameter")
    pulley_key = motor_pulley_key(params, stage)
    at = _in_link(stage, _pulley_frame(lay))
    parts.append(Part(f"{j}_motor_pulley", pulley_key, link, "purchased",
                      mounts.joint_pulley(params, j, teeth, bore, outboard=True, hub_node=hub), at,
                      mass=params.purchased(pulley_key).num("mass"), color=ALUMINIUM,
                      note=mounts.pulley_note(params, j, teeth, bore, set_screws=True, hub_node=hub)))
    set_screw = mounts.joint_set_screw(params, hub)
    parts += [purchased.set_screw(params, f"{j}_motor_pulley_set_screw_{i}", set_screw, link, at * f)
              for i, f in enumerate(mounts.set_screw_frames(params, j, bore, outboard=True, hub=hub))]
    return parts


def plate_tools(params: HeadParameters, stage: Stage) -> list[cq.Shape]:
    """What the plate needs for the stage (link frame): the jackshaft's passage and the housing's fixings, slots
    `slot` long along the stage frame's x, so the housing slides to tension the belt."""
    n, lay = node(params, stage), layout(params, stage)
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
    return [placed(stage, t) for t in out]
