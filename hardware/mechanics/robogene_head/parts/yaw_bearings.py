# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The yaw joint's bearings (geometry.yaw_bearings): two deep-groove ball bearings in a boss on the head floor, around
the fixed yaw shaft of the roll stage, spaced along it so that the pair carries the head's tipping moment as two radial
loads (robogene_head/bearing_loads.py checks them).

The arrangement is cross-located: the outer rings turn with the head against the load, so they are the tight rings
(fits: housing_turning_ring), each pressed into the boss against the land between them; the inner rings slide on the
shaft (journal_standing_ring) and are held from outside by a DIN 471 ring in a groove of the shaft, on a turned steel
spacer ring that bears on the inner ring alone: a DIN 988 shim for the 15 mm shaft (15 x 21) would reach over the
61802's seal, which turns with the outer ring (bearing_arrangement.shim_faces), and DIN 988 has no smaller one for a
15 mm bore. The head's weight goes land -> lower outer ring -> balls -> lower inner ring -> spacer -> lower ring ->
shaft; a pull upwards the same way through the upper bearing. The span between the two is short and both parts are
aluminium, so nothing grows against them; the axial play is set at assembly by facing the upper spacer to length.

Frames: z along the yaw axis, 0 on the head floor's top face (the yaw joint frame); the roll link's shaft is the same
line, zy = joints.neck_yaw.origin[2] higher in the roll link's frame."""
from __future__ import annotations

from dataclasses import dataclass

import cadquery as cq

from robogene_head_model.params import HeadParameters, ParameterError

from .. import geom
from . import neck, purchased
from .base import DARK, STEEL, Part, loc

SPACER_NOTE = ("Spacer ring between a yaw bearing's inner ring and its DIN 471 ring, turned from steel, faces flat and "
               "parallel; the upper one is faced to length at assembly for the yaw's axial play")
HOUSING_NOTE = ("Yaw bearing boss: two bearing seats pressed from either end against the land between them, "
                "coaxial as the fits line says; the wider bore under the lower seat clears the shaft's retaining ring")


@dataclass(frozen=True)
class Layout:
    """Where everything sits along the yaw axis (mm, head frame) and what size it is."""
    bearing: str              # catalogue keys
    ring: str
    spacer: tuple[float, float]   # the spacer rings' outside diameter and thickness
    width: float              # the bearings'
    outside: float
    bore: float
    lower: float              # each bearing's lower face
    upper: float
    ring_lower: float         # each ring's and spacer's lower face
    spacer_lower: float
    spacer_upper: float
    ring_upper: float
    groove_lower: tuple[float, float]   # each groove's extent on the shaft
    groove_upper: tuple[float, float]
    top: float                # the boss's top face
    shaft_end: float          # the yaw shaft's upper end
    boss: float               # diameters: the boss, the bore between the seats, the bore round the lower ring
    land_hole: float
    relief: float

    @property
    def span(self) -> float:
        return self.upper - self.lower


def _node(params: HeadParameters):
    return params.geometry("yaw_bearings")


def layout(params: HeadParameters) -> Layout:
    """The bearings, spacers and rings along the yaw axis from the parameters, refused where a ring or spacer could rub
    what turns or the boss has no land."""
    node = _node(params)
    path = "geometry.yaw_bearings"
    key = params.drive("neck_yaw").text("bearing")
    bearing = params.purchased(key)
    bore, outside, width = bearing.num("bore"), bearing.num("outside"), bearing.num("width")
    ring_key = node.text("shaft_ring")
    ring = params.purchased(ring_key)
    if ring.text("kind") != "shaft_ring":
        raise ParameterError(f"{params.path}: {path}.shaft_ring: {ring_key} is a {ring.text('kind')}, not a shaft ring")
    if abs(ring.num("shaft") - bore) > 1e-9:
        raise ParameterError(f"{params.path}: {path}: {ring_key} (for a {ring.num('shaft'):g} mm shaft) must fit the "
                             f"{bore:g} mm yaw shaft of the {key}")
    inner_ring = bearing.num("inner_ring_outside", positive=True)
    spacer = node.node("spacer")
    so, s = spacer.num("outside", positive=True), spacer.num("thickness", positive=True)
    if not bore < so <= inner_ring:
        raise ParameterError(f"{params.path}: {path}.spacer.outside: {so:g} must be over the {bore:g} mm shaft and "
                             f"within the {key}'s inner ring's face ({inner_ring:g} across): beyond it the spacer lies "
                             f"on the seal, which turns with the outer ring while the spacer stands still")
    lugs = ring.num("lug_outer_diameter", positive=True)
    if lugs > inner_ring and s < neck.LUG_GAP:   # the floating bearings' rule for their rings' lugs
        raise ParameterError(f"{params.path}: {path}.spacer.thickness: the {ring_key} ring's lugs reach out to {lugs:g}, "
                             f"beyond the {key}'s inner ring ({inner_ring:g} across), over its seal and outer ring, "
                             f"which turn while they stand still: a spacer at least {neck.LUG_GAP:g} thick must keep "
                             f"them off (this one: {s:g})")
    span = node.num("span", positive=True)
    if span < width + 1:
        raise ParameterError(f"{params.path}: {path}.span: {span:g} leaves under 1 mm of land between the two "
                             f"{width:g} mm wide bearings")
    land = node.num("land_hole", positive=True)
    gap = params.geometry("clearances").num("minimum", positive=True)
    if not (bore + 2 * gap <= land and inner_ring < land < outside):
        raise ParameterError(f"{params.path}: {path}.land_hole: {land:g} must clear the {bore:g} mm shaft by "
                             f"{gap:g} and the inner rings ({inner_ring:g} across), and leave a shoulder for the "
                             f"{outside:g} mm outer rings")
    ft = params.geometry("head", "floor").num("thickness", positive=True)
    t, m = ring.num("thickness", positive=True), ring.num("groove_width", positive=True)
    if m < t:
        raise ParameterError(f"{params.path}: purchased.{ring_key}: groove_width {m:g} is narrower than the ring ({t:g})")
    ring_lower = -ft                       # on the floor's underside: the pulley below keeps its plate gap
    spacer_lower = ring_lower + t
    lower = spacer_lower + s
    upper = lower + span
    top = upper + width
    spacer_upper = top
    ring_upper = spacer_upper + s
    # each ring bears on the groove's wall away from its bearing
    groove_lower = (ring_lower, ring_lower + m)
    groove_upper = (ring_upper + t - m, ring_upper + t)
    shaft_end = groove_upper[1] + ring.num("groove_edge", positive=True)
    return Layout(key, ring_key, (so, s), width, outside, bore, lower, upper, ring_lower, spacer_lower, spacer_upper,
                  ring_upper, groove_lower, groove_upper, top, shaft_end,
                  outside + 2 * node.num("wall", positive=True), land, lugs + 2 * gap)


def boss(params: HeadParameters) -> cq.Shape:
    """The boss that stands on the floor's top face (z 0) up to the upper seat's end."""
    lay = layout(params)
    return geom.cyl("z", lay.boss, -1, lay.top)


def housing_tools(params: HeadParameters) -> list[cq.Shape]:
    """The bores through floor and boss: round the lower ring, the two seats, the land between them."""
    lay = layout(params)
    ft = params.geometry("head", "floor").num("thickness")
    return [geom.cyl("z", lay.relief, -ft - 1, lay.lower),
            geom.cyl("z", lay.outside, lay.lower, lay.lower + lay.width),
            geom.cyl("z", lay.land_hole, lay.lower + lay.width - 0.5, lay.upper + 0.5),
            geom.cyl("z", lay.outside, lay.upper, lay.top + 1)]


def shaft_grooves(params: HeadParameters, zy: float) -> list[cq.Shape]:
    """The two ring grooves on the yaw shaft, in the roll link's frame (zy: the yaw joint's height there)."""
    lay = layout(params)
    d2 = params.purchased(lay.ring).num("groove_diameter", positive=True)
    return [geom.tube("z", lay.bore + 1, d2, zy + z0, zy + z1) for z0, z1 in (lay.groove_lower, lay.groove_upper)]


def shaft_end(params: HeadParameters) -> float:
    """The yaw shaft's upper end along the axis, head frame (what a sensor above it faces)."""
    return layout(params).shaft_end


def head_parts(params: HeadParameters) -> list[Part]:
    """The two bearings, in the head floor's boss (head frame)."""
    lay = layout(params)
    return [purchased.bearing(params, f"neck_yaw_bearing_{which}", lay.bearing, "head_frame", loc(z=z))
            for which, z in (("lower", lay.lower), ("upper", lay.upper))]


def shaft_parts(params: HeadParameters, zy: float) -> list[Part]:
    """The spacer rings and DIN 471 rings on the yaw shaft (roll link frame)."""
    lay = layout(params)
    ring = params.purchased(lay.ring)
    ring_shape = geom.tube("z", ring.num("outside_diameter", positive=True), ring.num("groove_diameter"), 0,
                           ring.num("thickness"))
    spacer_shape = geom.tube("z", lay.spacer[0], lay.bore, 0, lay.spacer[1])
    out = []
    for which, z_spacer, z_ring in (("lower", lay.spacer_lower, lay.ring_lower),
                                    ("upper", lay.spacer_upper, lay.ring_upper)):
        out.append(Part(f"neck_yaw_spacer_{which}", "neck_yaw_spacer", "neck_roll_link", "machined", spacer_shape,
                        loc(z=zy + z_spacer), note=SPACER_NOTE, material="steel", color=STEEL))
        out.append(Part(f"neck_yaw_ring_{which}", lay.ring, "neck_roll_link", "purchased", ring_shape,
                        loc(z=zy + z_ring), mass=ring.num("mass"), color=DARK))
    return out
