# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The four M2 screws that hold a gearhead by its flange, and the holes they need in the plate it bears on.

Work in a flange frame: the plate lies in z 0..thickness with the gearhead's axis at the origin and its flange on
z = thickness. The screws come from z = 0 with their heads sunk in ISO 4762 counterbores, because that side faces
a bearing, a pulley or an eye cup; each one reaches ENGAGEMENT into the gearhead's thread. A plate too thin for
counterbores (the yaw mount) has its screw heads under it, in pockets of what it stands on."""
from __future__ import annotations

import cadquery as cq

from .. import geom
from ..params import HeadParameters, ParameterError
from . import purchased
from .base import Part, loc

CLEARANCE = 2.2            # M2, ISO 273 fine: the screws also centre the gearhead
COUNTERBORE = (4.4, 2.2)   # diameter, depth for an ISO 4762 M2 head (3.8 x 2)
ENGAGEMENT = 4.2
NOTE = "4 x 2.2 on the gearhead's bolt circle, counterbored 4.4 x 2.2 deep on the side away from the gearhead"


def holes(gearhead_diameter: float, thickness: float, counterbores: bool = True) -> list[cq.Shape]:
    """Cutting tools in the flange frame."""
    out = []
    for c in purchased.gearhead_bolt_circle(gearhead_diameter):
        out.append(geom.cyl("z", CLEARANCE, -1, thickness + 1, c))
        if counterbores:
            out.append(geom.cyl("z", COUNTERBORE[0], -1, COUNTERBORE[1], c))
    return out


def screw_key(thickness: float) -> str:
    """ISO 4762 M2 length that reaches ENGAGEMENT into the gearhead through a counterbored plate this thick."""
    return f"iso4762-M2x{thickness - COUNTERBORE[1] + ENGAGEMENT:g}"


def screws(params: HeadParameters, name: str, link: str, flange_frame: cq.Location, gearhead_diameter: float,
           thickness: float, key: str | None = None, counterbored: bool = True) -> list[Part]:
    """The four screws; key defaults to screw_key(thickness) (counterbored plates)."""
    key = key or screw_key(thickness)
    if not params.root.node("purchased").has(key):
        raise ParameterError(f"{params.path}: purchased: no {key!r} for the gearhead screws of {name} "
                             f"(plate {thickness:g} mm thick)")
    seat = COUNTERBORE[1] if counterbored else 0.0
    reach = params.purchased(key).num("length") - (thickness - seat)
    if not 2 <= reach <= purchased.GEARHEAD_THREAD_DEPTH:
        raise ParameterError(f"{params.path}: purchased.{key}: reaches {reach:g} mm into {name}'s gearhead threads, "
                             f"which take 2 to {purchased.GEARHEAD_THREAD_DEPTH:g} mm")
    return [purchased.screw(params, f"{name}_gearhead_screw_{k}", key, link, flange_frame * loc(x, y, seat))
            for k, (x, y) in enumerate(purchased.gearhead_bolt_circle(gearhead_diameter))]


def head_pockets(gearhead_diameter: float, slot: float = 0.0) -> list[cq.Shape]:
    """Pockets for the heads of screws under a plate without counterbores, in the flange frame (z < 0), as slots
    `slot` long along x when the plate slides."""
    d, depth = COUNTERBORE
    out = []
    for x, y in purchased.gearhead_bolt_circle(gearhead_diameter):
        out += [geom.cyl("z", d, -depth, 1, (x - slot / 2, y)), geom.cyl("z", d, -depth, 1, (x + slot / 2, y))]
        if slot > 0:
            out.append(geom.box(x - slot / 2, x + slot / 2, y - d / 2, y + d / 2, -depth, 1))
    return out
