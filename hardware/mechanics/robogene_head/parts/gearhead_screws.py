# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The four M2 screws that hold a gearhead by its flange, and the holes they need in the plate it bears on.

Work in a flange frame: the plate lies in z 0..thickness with the gearhead's axis at the origin and its flange on
z = thickness. The screws come from z = 0 with their heads sunk in ISO 4762 counterbores, because that side faces
a bearing, a pulley or an eye cup; each one reaches geometry.gearhead_flange.engagement into the gearhead's
thread. A plate too thin for counterbores (the yaw mount) has its screw heads under it, in pockets of what it
stands on."""
from __future__ import annotations

import cadquery as cq

from robogene_head_model.params import HeadParameters, Node, ParameterError

from .. import geom
from . import purchased
from .base import Part, loc


def flange(params: HeadParameters) -> Node:
    return params.geometry("gearhead_flange")


def clearance(params: HeadParameters) -> float:
    """M2 clearance, ISO 273 fine: the screws also centre the gearhead."""
    return flange(params).num("clearance", positive=True)


def counterbore(params: HeadParameters) -> tuple[float, float]:
    """Diameter and depth of the counterbore for an ISO 4762 M2 head."""
    d, depth = flange(params).vec("counterbore", 2)
    if d <= clearance(params) or depth <= 0:
        raise ParameterError(f"{params.path}: geometry.gearhead_flange.counterbore: expected a diameter above the "
                             f"clearance ({clearance(params):g}) and a positive depth, got {[d, depth]}")
    return d, depth


def note(params: HeadParameters) -> str:
    """What a drawing says about the holes."""
    d, depth = counterbore(params)
    return (f"4 x {clearance(params):g} on the gearhead's bolt circle, counterbored {d:g} x {depth:g} deep on the side "
            f"away from the gearhead")


def holes(params: HeadParameters, gearhead_diameter: float, thickness: float, counterbores: bool = True) -> list[cq.Shape]:
    """Cutting tools in the flange frame."""
    out = []
    d, depth = counterbore(params)
    for c in purchased.gearhead_bolt_circle(params, gearhead_diameter):
        out.append(geom.cyl("z", clearance(params), -1, thickness + 1, c))
        if counterbores:
            out.append(geom.cyl("z", d, -1, depth, c))
    return out


def screw_key(params: HeadParameters, thickness: float) -> str:
    """ISO 4762 M2 length that reaches the engagement into the gearhead through a counterbored plate this thick."""
    engagement = flange(params).num("engagement", positive=True)
    return f"iso4762-M2x{thickness - counterbore(params)[1] + engagement:g}"


def screws(params: HeadParameters, name: str, link: str, flange_frame: cq.Location, gearhead_diameter: float,
           thickness: float, key: str | None = None, counterbored: bool = True) -> list[Part]:
    """The four screws; key defaults to screw_key(thickness) (counterbored plates)."""
    key = key or screw_key(params, thickness)
    if not params.root.node("purchased").has(key):
        raise ParameterError(f"{params.path}: purchased: no {key!r} for the gearhead screws of {name} "
                             f"(plate {thickness:g} mm thick)")
    seat = counterbore(params)[1] if counterbored else 0.0
    reach = params.purchased(key).num("length") - (thickness - seat)
    thread_depth = flange(params).num("thread_depth", positive=True)
    if not 2 <= reach <= thread_depth:
        raise ParameterError(f"{params.path}: purchased.{key}: reaches {reach:g} mm into {name}'s gearhead threads, "
                             f"which take 2 to {thread_depth:g} mm")
    return [purchased.screw(params, f"{name}_gearhead_screw_{k}", key, link, flange_frame * loc(x, y, seat))
            for k, (x, y) in enumerate(purchased.gearhead_bolt_circle(params, gearhead_diameter))]
