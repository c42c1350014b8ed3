# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Hard stops of the eye pan joints, which have no joint encoder: each eye finds its zero against one at power-up
(homing: in the parameter file).

A lug hangs from the back of each eye cup at geometry.eyes.hard_stop.radius from the pan axis; two dowel pins
pressed into the tilt frame's plate stand in its path. The pins sit where the lug's side face meets them exactly
at the joint's stop angles (homing.<joint>.stops_deg), just beyond its limits, so the interference sweep sees the
lug clear of them over the whole range and a test sees it strike them at the stops. Angles follow the joint's
axis (pan turns about -z of the tilt frame: a positive pan moves the lug clockwise seen from above)."""
from __future__ import annotations

import math

import cadquery as cq

from robogene_head_model.params import HeadParameters, Node, ParameterError

from .. import geom
from . import purchased
from .base import Part, loc

PAN_JOINTS = ("left_eye_pan", "right_eye_pan")
PIN_NOTE = "Eye-pan hard stops: 4 x ⌀3 through, ream H7 for pressed dowel pins ISO 8734 3 m6."


def stop(params: HeadParameters) -> Node:
    return params.geometry("eyes", "hard_stop")


def stops_deg(params: HeadParameters, joint: str) -> tuple[float, float]:
    """(lower, upper) stop angles of a pan joint, checked to lie beyond its limits."""
    node = params.root.node("homing").node(joint)
    lo, hi = node.vec("stops_deg", 2)
    j = params.joints[joint]
    if not lo < j.lower < j.upper < hi:
        raise node.fail("stops_deg", f"expected lower stop < {j.lower:g} and upper stop > {j.upper:g} (the joint's "
                                      f"limits), got {[lo, hi]}")
    return lo, hi


def half_angle(params: HeadParameters) -> float:
    """Degrees between the lug's centre line and a pin's centre when the lug's side face touches the pin."""
    s = stop(params)
    pin = params.purchased(s.text("pin"))
    reach = s.num("lug_width", positive=True) / 2 + pin.num("diameter", positive=True) / 2
    radius = s.num("radius", positive=True)
    if reach >= radius:
        raise ParameterError(f"{params.path}: geometry.eyes.hard_stop.radius: {radius:g} is too small for the lug "
                             f"and pin ({reach:g} from the lug's centre line)")
    return math.degrees(math.asin(reach / radius))


def lug(params: HeadParameters, z_plate_top: float) -> cq.Shape:
    """The lug in the eye's frame, at the back of the cup (-x), hanging down to lug_gap above the plate's top."""
    s = stop(params)
    r, w, radial = s.num("radius", positive=True), s.num("lug_width", positive=True), s.num("lug_depth", positive=True)
    cup = params.geometry("eyes").num("cup_radius", positive=True)
    bottom = z_plate_top + s.num("lug_gap", positive=True)
    # up into the cup: a little past the sphere's surface at the lug's inner edge, so the two are one solid
    top = -math.sqrt(cup * cup - (r - radial / 2) ** 2) + 0.5
    if top <= bottom:
        raise ParameterError(f"{params.path}: geometry.eyes.hard_stop: the lug has no height between the plate and "
                             f"the cup at radius {r:g}")
    return geom.box(-r - radial / 2, -r + radial / 2, -w / 2, w / 2, bottom, top)


def pin_angles(params: HeadParameters, joint: str) -> list[float]:
    """Where the pins' centres sit, in degrees about +z of the tilt frame from +x, for a lug at 180 deg at zero."""
    lo, hi = stops_deg(params, joint)
    a = half_angle(params)
    # pan turns about -z: at angle q the lug's centre is at 180 - q
    return [180 - hi - a, 180 - lo + a]


def pins(params: HeadParameters, joint: str, eye_y: float, z_plate_top: float, link: str) -> tuple[list[Part], list]:
    """The two stop pins of a pan joint (pressed from above into the plate) and their holes' tools."""
    s = stop(params)
    key = s.text("pin")
    pin = params.purchased(key)
    depth = s.num("pin_depth", positive=True)
    length = pin.num("length", positive=True)
    if depth >= length:
        raise ParameterError(f"{params.path}: geometry.eyes.hard_stop.pin_depth: {depth:g} leaves nothing of the "
                             f"{length:g} mm pin above the plate")
    r = s.num("radius", positive=True)
    parts, holes = [], []
    for i, angle in enumerate(pin_angles(params, joint)):
        x, y = r * math.cos(math.radians(angle)), eye_y + r * math.sin(math.radians(angle))
        parts.append(purchased.pin(params, f"{joint}_stop_pin_{i}", key, link, loc(x, y, z_plate_top - depth)))
        holes.append(geom.cyl("z", pin.num("diameter"), z_plate_top - depth, z_plate_top + 1, (x, y)))
    return parts, holes
