# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The screws that hold the head frame together, and the holes they need.

The side plates and the back plate stand on the floor, bolted from below; the back plate and the top bar
sit between the side plates, bolted through them (geometry.head.joins). Clearance holes are
geometry.clearance_holes; tapped holes are drawn at the thread's nominal diameter, as everywhere in the head."""
from __future__ import annotations

from dataclasses import dataclass, field

import cadquery as cq

from robogene_head_model.params import HeadParameters, Node

from .. import geom
from . import mounts, purchased
from .base import Part, loc

M3, M2 = "iso7380-M3x12", "iso4762-M2x10"


def _joins(params: HeadParameters) -> Node:
    """geometry.head.joins: where the screws go and how deep their threads are tapped."""
    return params.geometry("head", "joins")


def tap_depth(params: HeadParameters) -> float:
    return _joins(params).num("tap_depth", positive=True)


def notes(params: HeadParameters) -> dict[str, str]:
    """Drawing notes: what the drawn holes of each part are."""
    c3, c2 = mounts.clearance_hole(params, M3), mounts.clearance_hole(params, M2)
    depth = tap_depth(params)
    return {
        "head_floor": f"{c3:g} / {c2:g}: clearance for the side and back plates' M3 / M2; {c3:g} slots for the yaw "
                      f"jackshaft housing's M3 and the jackshaft's passage, along the belt (belt tension)",
        "head_side_plate": f"M3 tapped {depth:g} deep (tap drill 2.5) in front and bottom edges, drawn at 3.0; {c2:g} "
                           f"through for M2; left plate: {c3:g} slots for the tilt jackshaft housing's M3 and the "
                           f"jackshaft's passage, along x (belt tension)",
        "head_back_plate": f"M2 tapped {depth:g} deep (tap drill 1.6) in bottom and side edges, drawn at 2.0",
        "head_top_bar": f"4 x M2 tapped {depth:g} deep (tap drill 1.6) in the ends, drawn at 2.0",
    }


@dataclass
class Joins:
    holes: dict[str, list[cq.Shape]] = field(default_factory=dict)   # design -> tools, in the design frame
    screws: list[Part] = field(default_factory=list)

    def add(self, design: str, *tools: cq.Shape) -> None:
        self.holes.setdefault(design, []).extend(tools)


def build(params: HeadParameters) -> Joins:
    h = params.geometry("head")
    fl, sp, bp, tb = h.node("floor"), h.node("side_plate"), h.node("back_plate"), h.node("top_bar")
    x0, hw, ft = fl.num("x_min"), fl.num("half_width"), fl.num("thickness")
    st, sh = sp.num("thickness"), sp.num("height")
    bt = bp.num("thickness")
    inner = hw - st
    d3, d2 = params.purchased(M3).num("diameter"), params.purchased(M2).num("diameter")
    clearance = {d3: mounts.clearance_hole(params, M3), d2: mounts.clearance_hole(params, M2)}
    j = _joins(params)
    depth = tap_depth(params)
    joins = Joins()

    # Side plates on the floor: the left plate's holes; the right plate is its mirror image.
    y_side = inner + st / 2
    for i, x in enumerate(j.vec("side_floor_x", 2)):
        joins.add("head_side_plate", geom.cyl("z", d3, -1, depth, (x, y_side)))
        for side, sign in (("left", 1), ("right", -1)):
            joins.add("head_floor", geom.cyl("z", clearance[d3], -ft - 1, 1, (x, sign * y_side)))
            joins.screws.append(purchased.screw(params, f"side_floor_screw_{side}_{i}", M3, "head_frame",
                                                loc(x, sign * y_side, -ft)))

    # Back plate on the floor.
    x_back = x0 + bt / 2
    for i, y in enumerate(j.vec("back_floor_y", 2)):
        joins.add("head_back_plate", geom.cyl("z", d2, -1, depth, (x_back, y)))
        joins.add("head_floor", geom.cyl("z", clearance[d2], -ft - 1, 1, (x_back, y)))
        joins.screws.append(purchased.screw(params, f"back_floor_screw_{i}", M2, "head_frame", loc(x_back, y, -ft)))

    # Back plate and top bar between the side plates: M2 through the side plates into their edges.
    top_x = tb.num("x") + tb.num("width") / 2
    top_z = sh - tb.num("thickness") / 2
    through = [("back", "head_back_plate", x_back, z) for z in j.vec("back_side_z", 2)] + \
              [("top", "head_top_bar", top_x + dx, top_z) for dx in j.vec("top_side_dx", 2)]
    for i, (what, design, x, z) in enumerate(through):
        joins.add("head_side_plate", geom.cyl("y", clearance[d2], inner - 1, hw + 1, (x, z)))
        joins.add(design, geom.cyl("y", d2, inner - depth, inner + 1, (x, z)),
                  geom.cyl("y", d2, -inner - 1, -inner + depth, (x, z)))
        for side, sign in (("left", 1), ("right", -1)):
            # the shank points into the head: -y on the left, +y on the right
            joins.screws.append(purchased.screw(params, f"{what}_side_screw_{side}_{i}", M2, "head_frame",
                                                loc(x, sign * hw, z, rx=90 * sign)))
    return joins
