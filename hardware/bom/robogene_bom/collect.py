# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Quantities per head: purchased parts counted in the CAD assembly, belts derived from the pulleys, and
the parts of every KiCad board BOM; each looked up in the catalog. Made parts are listed with their process."""
from __future__ import annotations

import math
from collections import Counter, OrderedDict
from dataclasses import dataclass, field
from pathlib import Path

from robogene_head.geom import exact_bounds

from . import board
from .catalog import Catalog, CatalogError, Item


@dataclass
class Line:
    item: Item
    per_head: float    # pieces, or metres for parts bought by length
    used_in: list[str] = field(default_factory=list)   # part instances or board references

    def ordered(self, heads: int) -> int:
        """What to order for `heads` heads: pieces, or whole metres of a part bought by length."""
        if self.item.unit == "m":
            return max(1, math.ceil(self.per_head * heads - 1e-9))
        return int(round(self.per_head * heads))


def exact_size(shape) -> tuple[float, float, float]:
    """The shape's size from its geometry alone (see geom.exact_bounds: a triangulation must not change a price)."""
    lo, hi = exact_bounds(shape)
    return tuple(float(v) for v in hi - lo)


@dataclass
class MadePart:
    design: str
    kind: str          # machined / printed
    material: str
    per_head: int
    volume_mm3: float = 0.0                     # the finished part
    size_mm: tuple[float, float, float] = (0.0, 0.0, 0.0)   # its bounding box


@dataclass
class Bom:
    lines: list[Line]
    made: list[MadePart]
    currency: str
    boards: list[str]

    def cost_per_head(self, heads: int = 1) -> float:
        """Cost of the purchased parts of one head when `heads` heads are ordered together."""
        return sum(line.ordered(heads) * line.item.unit_price(line.ordered(heads)) for line in self.lines) / heads


def collect(parts, belts, board_boms: list[tuple[Path, int]], catalog: Catalog, pcb_key: str | None = None,
            extras: list[tuple[str, float, str]] = ()) -> Bom:
    """parts: robogene_head Part objects; belts: (catalog key, joint, teeth) from mounts.belts;
    board_boms: (CSV path, copies of that board per head); pcb_key: catalog key of a bare board, one per copy;
    extras: (catalog key, quantity per head, what it is for): the harness's parts and what the head needs besides
    its own parts (supply, CAN adapter, computer, board assembly)."""
    counts: OrderedDict[str, list[str]] = OrderedDict()
    for part in parts:
        if part.kind == "purchased":
            counts.setdefault(part.design, []).append(part.name)
    for key, joint, teeth in belts:
        if key in counts:   # placed in the assembly, counted with the parts
            continue
        counts.setdefault(key, []).append(f"{joint} belt ({teeth} teeth)")
    lines = [Line(catalog.get(key, f"CAD part {users[0]}"), len(users), users) for key, users in counts.items()]
    by_mpn = catalog.by_mpn()
    board_names = []

    def add(item: Item, quantity: int, user: str) -> None:
        existing = next((l for l in lines if l.item.key == item.key), None)
        if existing is None:
            existing = Line(item, 0, [])
            lines.append(existing)
        existing.per_head += quantity
        existing.used_in.append(user)

    for path, copies in board_boms:
        if copies < 1:
            raise CatalogError(f"{path}: copies per head must be >= 1, got {copies}")
        name = path.parent.name if path.stem == "bom" else path.stem   # build/fab/electronics/bom.csv -> electronics
        board_names.append(f"{name} x{copies}" if copies > 1 else name)
        for entry in board.read(path):
            item = by_mpn.get(entry.mpn.casefold())
            if item is None:
                raise CatalogError(f"{catalog.path}: no entry with mpn {entry.mpn!r} (needed by {entry.source}, "
                                   f"{entry.references or entry.value}); add it under parts:")
            add(item, entry.quantity * copies, f"{path.stem}: {entry.references}")
        if pcb_key:
            add(catalog.get(pcb_key, f"board BOM {path.name}"), copies, f"{path.stem}: bare board")
    for key, quantity, user in extras:
        add(catalog.get(key, user), quantity, user)
    made_counts = Counter((p.design, p.kind, p.material) for p in parts if p.kind in ("machined", "printed"))
    first = {}
    for p in parts:
        first.setdefault(p.design, p)

    def made_part(d, k, m, n):
        return MadePart(d, k, m, n, first[d].local.Volume(), exact_size(first[d].local))
    made = [made_part(d, k, m, n) for (d, k, m), n in sorted(made_counts.items(), key=lambda t: (t[0][1], t[0][0]))]
    return Bom(lines, made, catalog.currency, board_names)
