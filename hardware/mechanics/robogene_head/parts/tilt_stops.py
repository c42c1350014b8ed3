# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Hard stops of the eye tilt: what stops the tilt frame mechanically past its range. The joint finds its zero from
its absolute joint encoder; the stops keep a runaway (or a hand) from turning the eyes into the head's frame.

Two dowel pins pressed into each side plate's inner face stand into the path of the tilt frame's arm, below the
tilt axis: one in front of the arm, one behind it. Each sits where the arm's front or back face meets it exactly at
geometry.eyes.tilt_stop.stops_deg, just beyond the joint's limits, `depth` below the axis along the arm, so the
interference sweep sees the arm clear of the pins over the whole range and a test sees it strike them at the stops.
Tilt turns about -y of the head frame: a positive tilt lifts the front, swinging the arm's lower end forward."""
from __future__ import annotations

import math

from .. import geom
from robogene_head_model.params import HeadParameters, Node
from . import purchased
from .base import Part, loc

PIN_NOTE = "Eye-tilt hard stops: 2 x ⌀3 blind in the inner face, ream H7 for pressed dowel pins ISO 8734 3 m6."


def stop(params: HeadParameters) -> Node:
    return params.geometry("eyes", "tilt_stop")


def stops_deg(params: HeadParameters) -> tuple[float, float]:
    """(lower, upper) stop angles of the eye tilt, checked to lie beyond its limits."""
    node = stop(params)
    lo, hi = node.vec("stops_deg", 2)
    j = params.joints["eyes_tilt"]
    if not lo < j.lower < j.upper < hi:
        raise node.fail("stops_deg", f"expected lower stop < {j.lower:g} and upper stop > {j.upper:g} (the joint's "
                                      f"limits), got {[lo, hi]}")
    return lo, hi


def arm_section(params: HeadParameters) -> tuple[float, float, float]:
    """The tilt frame's arm in the tilt link's x-z plane: half its length along x, its lowest and highest z (the
    plate's underside and the arm's top, parts/eyes.py)."""
    e = params.geometry("eyes")
    tf = e.node("tilt_frame")
    z_top = -e.num("cup_radius", positive=True) - e.num("gap", positive=True)
    return (tf.num("arm_length", positive=True) / 2, z_top - tf.num("plate_thickness", positive=True),
            tf.num("arm_height", positive=True))


def _rotate(q_deg: float, x: float, z: float) -> tuple[float, float]:
    """A point of the tilt link at tilt q, in the head frame's x-z axes about the tilt axis."""
    c, s = math.cos(math.radians(q_deg)), math.sin(math.radians(q_deg))
    return c * x - s * z, s * x + c * z


def pin_centres(params: HeadParameters) -> list[tuple[float, float]]:
    """(x, z) of the two pins about the tilt axis, head frame: behind the arm for the lower stop, in front of it for
    the upper one."""
    node = stop(params)
    pin = params.purchased(node.text("pin"))
    rp = pin.num("diameter", positive=True) / 2
    half, z_low, _ = arm_section(params)
    depth = node.num("depth", positive=True)
    if not rp < depth < -z_low - rp:
        raise node.fail("depth", f"{depth:g} puts the pins off the arm's faces (they run {-z_low:g} below the axis)")
    lo, hi = stops_deg(params)
    return [_rotate(lo, -(half + rp), -depth), _rotate(hi, half + rp, -depth)]


def pins(params: HeadParameters, inner: float, axis: tuple[float, float], link: str) -> tuple[list[Part], list]:
    """The four stop pins (two in each side plate's inner face at |y| = inner, standing in towards the arms) and the
    left plate's hole tools (the right plate is its mirror image)."""
    node = stop(params)
    key = node.text("pin")
    pin = params.purchased(key)
    depth, length = node.num("pin_depth", positive=True), pin.num("length", positive=True)
    plate = params.geometry("head", "side_plate").num("thickness", positive=True)
    if not 0 < depth < min(length, plate):
        raise node.fail("pin_depth", f"{depth:g}: a pin {length:g} long must stand out of a {plate:g} mm plate")
    tx, tz = axis
    parts, holes = [], []
    for i, (x, z) in enumerate(pin_centres(params)):
        x, z = tx + x, tz + z
        stand = length - depth   # how far the pin stands in from the plate's inner face
        parts.append(purchased.pin(params, f"eyes_tilt_stop_pin_left_{i}", key, link,
                                   loc(x, inner - stand, z, rx=-90)))
        parts.append(purchased.pin(params, f"eyes_tilt_stop_pin_right_{i}", key, link,
                                   loc(x, -inner + stand, z, rx=90)))
        holes.append(geom.cyl("y", pin.num("diameter"), inner - 1, inner + depth, (x, z)))
    return parts, holes

