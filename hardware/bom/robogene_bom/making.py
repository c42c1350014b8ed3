# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""An estimate, stated as such, of what making the head's own parts costs: machined parts from their stock block
(the part's bounding box plus a margin on every side, at the material's density and price per kg), a cycle time
per piece (a fixed handling time plus the stock removed at a removal rate) and a set-up per design per batch;
printed parts from their mass of filament and their printing time. The rates are `bom.making` in the parameter
file: shop rates, not quotes."""
from __future__ import annotations

from dataclasses import dataclass

from .collect import Bom, MadePart


@dataclass(frozen=True)
class Rates:
    machining_per_h: float
    setup_h: float
    cycle_min: float
    removal_cm3_per_min: float
    stock_margin: float
    stock_per_kg: float
    printing_per_h: float
    deposit_cm3_per_h: float
    filament_per_kg: float
    print_setup_h: float


def rates(params) -> Rates:
    m = params.root.node("bom").node("making")
    mc, pr = m.node("machining"), m.node("printing")
    return Rates(mc.num("rate_per_h", positive=True), mc.num("setup_h", minimum=0), mc.num("cycle_min", minimum=0),
                 mc.num("removal_cm3_per_min", positive=True), mc.num("stock_margin", minimum=0),
                 mc.num("stock_per_kg", positive=True), pr.num("rate_per_h", positive=True),
                 pr.num("deposit_cm3_per_h", positive=True), pr.num("filament_per_kg", positive=True),
                 pr.num("setup_h", minimum=0))


def unit_cost(part: MadePart, heads: int, r: Rates, density: float) -> float:
    """Cost of one piece when `heads` heads are made together (set-ups shared by all pieces of the batch)."""
    pieces = part.per_head * heads
    if part.kind == "machined":
        stock = 1.0
        for size in part.size_mm:
            stock *= size + 2 * r.stock_margin
        material = stock * 1e-9 * density * r.stock_per_kg
        minutes = r.cycle_min + max(stock - part.volume_mm3, 0.0) / 1000 / r.removal_cm3_per_min
        return material + minutes / 60 * r.machining_per_h + r.setup_h * r.machining_per_h / pieces
    hours = part.volume_mm3 / 1000 / r.deposit_cm3_per_h + r.print_setup_h
    return part.volume_mm3 * 1e-9 * density * r.filament_per_kg + hours * r.printing_per_h


def per_head(bom: Bom, params, heads: int) -> float:
    r = rates(params)
    densities = params.root.node("materials")
    return sum(m.per_head * unit_cost(m, heads, r, densities.num(m.material)) for m in bom.made)
