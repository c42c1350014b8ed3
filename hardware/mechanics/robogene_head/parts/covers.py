# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Printed covers: the head's back shell and the skirt around the board bay in the neck base (geometry.covers)."""
from __future__ import annotations

from robogene_head_model.params import HeadParameters, ParameterError

from .. import geom
from .base import PRINTED, Part


def build(params: HeadParameters) -> list[Part]:
    c = params.geometry("covers")
    wall, depth = c.num("wall", positive=True), c.num("back_depth", positive=True)
    exit_ = c.node("skirt_cable_exit")
    exit_w, exit_h = exit_.num("width", positive=True), exit_.num("height", positive=True)
    h = params.geometry("head")
    x0, hw = h.node("floor").num("x_min"), h.node("floor").num("half_width")
    ft, bh = h.node("floor").num("thickness"), h.node("back_plate").num("height")
    back = geom.cut(geom.box(x0 - depth, x0, -hw, hw, -ft, bh),
                    geom.box(x0 - depth + wall, x0 + 1, -hw + wall, hw - wall, -ft + wall, bh - wall))
    g = params.geometry("neck_base")
    L, W = g.node("plate").num("length"), g.node("plate").num("width")
    T, bay = g.node("plate").num("thickness"), g.num("bay_height")
    if exit_h >= bay:
        raise ParameterError(f"{params.path}: geometry.covers.skirt_cable_exit.height: {exit_h:g} leaves nothing of "
                             f"the skirt's wall above it (the bay is {bay:g} high)")
    skirt = geom.cut(geom.box(-L / 2, L / 2, -W / 2, W / 2, -T - bay, -T),
                     geom.box(-L / 2 + wall, L / 2 - wall, -W / 2 + wall, W / 2 - wall, -T - bay - 1, -T + 1),
                     geom.box(-L / 2 - 1, -L / 2 + wall + 1, -exit_w / 2, exit_w / 2, -T - bay - 1,
                              -T - bay + exit_h))  # cable exit
    return [
        Part("head_back_cover", "head_back_cover", "head_frame", "printed", geom.single_solid(back, "back cover"),
             material="petg-printed", color=PRINTED),
        Part("neck_base_skirt", "neck_base_skirt", "neck_base", "printed", geom.single_solid(skirt, "skirt"),
             material="petg-printed", color=PRINTED),
    ]
