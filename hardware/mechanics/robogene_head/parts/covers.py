# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Printed covers: the head's back shell and the skirt around the board bay in the neck base."""
from __future__ import annotations

from .. import geom
from ..params import HeadParameters
from .base import PRINTED, Part

WALL = 2.0


def build(params: HeadParameters) -> list[Part]:
    h = params.geometry("head")
    x0, hw = h.node("floor").num("x_min"), h.node("floor").num("half_width")
    ft, bh = h.node("floor").num("thickness"), h.node("back_plate").num("height")
    depth = 12.0
    back = geom.cut(geom.box(x0 - depth, x0, -hw, hw, -ft, bh),
                    geom.box(x0 - depth + WALL, x0 + 1, -hw + WALL, hw - WALL, -ft + WALL, bh - WALL))
    g = params.geometry("neck_base")
    L, W = g.node("plate").num("length"), g.node("plate").num("width")
    T, bay = g.node("plate").num("thickness"), g.num("bay_height")
    skirt = geom.cut(geom.box(-L / 2, L / 2, -W / 2, W / 2, -T - bay, -T),
                     geom.box(-L / 2 + WALL, L / 2 - WALL, -W / 2 + WALL, W / 2 - WALL, -T - bay - 1, -T + 1),
                     geom.box(-L / 2 - 1, -L / 2 + WALL + 1, -15, 15, -T - bay - 1, -T - bay + 10))  # cable exit
    return [
        Part("head_back_cover", "head_back_cover", "head_frame", "printed", geom.single_solid(back, "back cover"),
             material="petg-printed", color=PRINTED),
        Part("neck_base_skirt", "neck_base_skirt", "neck_base", "printed", geom.single_solid(skirt, "skirt"),
             material="petg-printed", color=PRINTED),
    ]
