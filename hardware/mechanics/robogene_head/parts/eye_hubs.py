# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The eye hubs: how each eye-pan gearhead's torque reaches its printed eye cup (torque_paths: in the parameter file).

An aluminium hub sits in a pocket under each cup. Its round neck takes the 16/7's output shaft, which stops short
of the cup, and is held on it by two cup-point set screws; its head above the shaft's end has two flats, and the
cup's pocket has the same two flats, so the cup cannot turn on it. The set screws are turned through two access
holes in the cup's bottom after the eye is on its shaft. Work in the eye's frame: the pan axis is z, the tilt
frame's plate top at z_plate_top."""
from __future__ import annotations

import math

import cadquery as cq

from robogene_head_model.params import HeadParameters, Node, ParameterError

from .. import geom
from . import purchased
from .base import ALUMINIUM, Part, loc


def hub(params: HeadParameters) -> Node:
    return params.geometry("eyes", "hub")


def _gearhead(params: HeadParameters) -> Node:
    return params.purchased(params.drive("left_eye_pan").text("gearhead"))


def levels(params: HeadParameters, z_plate_top: float) -> tuple[float, float, float]:
    """(bottom of the hub, the shaft's end = top of the neck, top of the head), z in the eye's frame. The gearhead's
    flange bears on the plate's underside, so its shaft ends shaft_length above that."""
    h = hub(params)
    plate = params.geometry("eyes", "tilt_frame").num("plate_thickness", positive=True)
    bottom = z_plate_top + h.num("gap", positive=True)
    shaft_end = z_plate_top - plate + _gearhead(params).num("shaft_length", positive=True)
    top = shaft_end + h.num("head_height", positive=True)
    screw = params.purchased(h.text("set_screw"))
    if shaft_end - bottom < screw.num("diameter") + 1:
        raise ParameterError(f"{params.path}: geometry.eyes.hub.gap: the neck holds only {shaft_end - bottom:.2f} mm "
                             f"of the pan shaft, under the set screw's diameter + 1 mm")
    return bottom, shaft_end, top


def flats_width(params: HeadParameters) -> float:
    """The head's width across its two flats."""
    h = hub(params)
    d, depth = h.num("head_diameter", positive=True), h.num("flat_depth", positive=True)
    if not 0 < depth < d / 2:
        raise ParameterError(f"{params.path}: geometry.eyes.hub.flat_depth: {depth:g} on a {d:g} mm head")
    return d - 2 * depth


def head_profile(params: HeadParameters, z0: float, z1: float, grow: float = 0.0) -> cq.Shape:
    """The head's D shape (flats facing +-y) from z0 to z1, grown by `grow` all round (the cup's pocket: 0)."""
    d = hub(params).num("head_diameter", positive=True) + 2 * grow
    half = flats_width(params) / 2 + grow
    return geom.cut(geom.cyl("z", d, z0, z1), geom.box(-d, d, half, d, z0 - 1, z1 + 1),
                    geom.box(-d, d, -d, -half, z0 - 1, z1 + 1))


def screw_angles(params: HeadParameters) -> list[float]:
    """Directions of the set screws (deg about +z from +x, towards the screw's driven end)."""
    return [float(a) for a in hub(params).vec("set_screw_angles", 2)]


def screw_height(params: HeadParameters, z_plate_top: float) -> float:
    bottom, shaft_end, _ = levels(params, z_plate_top)
    return (bottom + shaft_end) / 2


def shape(params: HeadParameters, z_plate_top: float) -> cq.Shape:
    """The hub in the eye's frame: neck, head, blind bore for the shaft and the set screws' tapped holes."""
    h = hub(params)
    bottom, shaft_end, top = levels(params, z_plate_top)
    neck = h.num("neck_diameter", positive=True)
    shaft = _gearhead(params).num("shaft_diameter", positive=True)
    screw = params.purchased(h.text("set_screw"))
    # the screw's cup point bears on the shaft with its driven end flush with the neck
    if abs(neck / 2 - screw.num("length") - shaft / 2) > 1e-6:
        raise ParameterError(f"{params.path}: geometry.eyes.hub.neck_diameter: {neck:g} leaves a "
                             f"{(neck - shaft) / 2:g} mm wall; the {h.text('set_screw')} set screw is "
                             f"{screw.num('length'):g} long (neck = shaft + 2 x screw length)")
    if h.num("head_diameter") <= neck:
        raise ParameterError(f"{params.path}: geometry.eyes.hub.head_diameter: not above the neck's {neck:g}")
    body = geom.union(geom.cyl("z", neck, bottom, shaft_end), head_profile(params, shaft_end, top))
    z = screw_height(params, z_plate_top)
    holes = [geom.cyl("x", screw.num("diameter"), 0, neck).moved(loc(0, 0, z, rz=a)) for a in screw_angles(params)]
    return geom.single_solid(geom.cut(body, geom.cyl("z", shaft, bottom - 1, shaft_end), *holes), "eye hub")


def cup_cuts(params: HeadParameters, z_plate_top: float, cup_radius: float) -> list[cq.Shape]:
    """What the cup loses to its hub: below the shaft's end the neck's and the head's outlines together, so the hub
    goes in from below head first; above it the head's D alone, whose flats take the torque; and the set screws'
    access holes."""
    h = hub(params)
    bottom, shaft_end, top = levels(params, z_plate_top)
    neck = h.num("neck_diameter", positive=True)
    access = h.num("access_diameter", positive=True)
    z = screw_height(params, z_plate_top)
    return ([geom.cyl("z", neck, bottom - 1, shaft_end), head_profile(params, bottom - 1, top)]
            + [geom.cyl("x", access, neck / 2 - 0.5, cup_radius + 1).moved(loc(0, 0, z, rz=a))
               for a in screw_angles(params)])


def parts(params: HeadParameters, side: str, link: str, z_plate_top: float) -> list[Part]:
    h = hub(params)
    out = [Part(f"{side}_eye_hub", "eye_hub", link, "machined", shape(params, z_plate_top),
                material="aluminium-6082", color=ALUMINIUM, note=note(params))]
    key = h.text("set_screw")
    r = h.num("neck_diameter", positive=True) / 2
    z = screw_height(params, z_plate_top)
    for i, a in enumerate(screw_angles(params)):
        c, s = math.cos(math.radians(a)), math.sin(math.radians(a))
        # driven end (z = 0 of the screw) flush with the neck, the point inwards on the shaft
        out.append(purchased.set_screw(params, f"{side}_eye_hub_set_screw_{i}", key, link,
                                       loc(r * c, r * s, z, rz=a, ry=-90)))
    return out


def note(params: HeadParameters) -> str:
    h = hub(params)
    shaft = _gearhead(params).num("shaft_diameter")
    screw = params.purchased(h.text("set_screw"))
    return (f"Bore ⌀{shaft:g} H7 blind; 2 x M{screw.num('diameter'):g} "
            f"tapped radially at {', '.join(f'{a:g}' for a in screw_angles(params))} deg for ISO 4029 cup-point set "
            f"screws; head flats {flats_width(params):g} across, to the cup's pocket.")
