# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Write the head's BOM files (CSV for ordering, made-parts CSV, Markdown, HTML) into one folder."""
from __future__ import annotations

import json
import re
from pathlib import Path

from . import catalog as catalog_mod
from . import collect, making, render


def write_package(params, parts, board_boms: list[Path], out: Path, batch: int | None = None,
                  catalog_path: Path | None = None, extras: list[tuple[str, float, str]] = ()) -> collect.Bom:
    """board_boms: CSV files, each merged boards.count times per head (the head uses one board design),
    or PATH:N to give another count. extras: (catalog key, quantity per head, what for), the harness's parts;
    bom.system in the parameters adds what the head needs besides its own parts."""
    from robogene_head.parts import mounts

    batch = batch if batch is not None else int(params.root.node("bom").num("batch", positive=True))
    if batch < 1:
        raise ValueError(f"batch must be >= 1, got {batch}")
    catalog = catalog_mod.load(catalog_path)
    boards = params.root.node("boards")
    copies = int(boards.num("count", positive=True))
    pcb = boards.text("pcb") if boards.has("pcb") else None
    bom = collect.collect(parts, mounts.belts(params), [_board_arg(b, copies) for b in board_boms], catalog, pcb,
                          list(extras) + system_lines(params, copies))
    out.mkdir(parents=True, exist_ok=True)
    name = params.root.text("name")
    (out / f"{name}-bom.csv").write_text(render.to_csv(bom, batch))
    costs = made_costs(params, bom, batch)
    (out / f"{name}-made-parts.csv").write_text(render.made_csv(bom, batch, costs))
    (out / f"{name}-bom.md").write_text(render.to_markdown(bom, batch, costs))
    (out / "sources.json").write_text(json.dumps({
        "batch": batch, "catalog": str(catalog.path),
        "board_boms": [{"path": str(p), "copies": n} for p, n in (_board_arg(b, copies) for b in board_boms)]}, indent=1))
    (out / f"{name}-bom.html").write_text(render.to_html(bom, batch, f"Robogene head rev {params.root['revision']}: "
                                                                     f"bill of materials", costs))
    return bom


def made_costs(params, bom: collect.Bom, batch: int) -> dict | None:
    """design -> (estimated unit cost making one head, making a batch); None without bom.making."""
    if not params.root.node("bom").has("making"):
        return None
    r = making.rates(params)
    density = params.root.node("materials")
    return {m.design: (making.unit_cost(m, 1, r, density.num(m.material)),
                       making.unit_cost(m, batch, r, density.num(m.material))) for m in bom.made}


def _board_arg(arg, default: int) -> tuple[Path, int]:
    """PATH or PATH:N (N copies of that board per head)."""
    text = str(arg)
    match = re.fullmatch(r"(.+):(\d+)", text)
    if match and not Path(text).exists():
        return Path(match.group(1)), int(match.group(2))
    return Path(text), default


def system_lines(params, boards: int) -> list[tuple[str, float, str]]:
    """bom.system: what the head needs to move besides its own parts (supply, CAN adapter, computer, board
    assembly), each {key, qty (a number, or `boards` for one per board), for}."""
    from robogene_head_model.params import Node, ParameterError

    node = params.root.node("bom")
    if not node.has("system"):
        return []
    listed = node.raw("system")
    if not isinstance(listed, list):
        raise ParameterError(f"{params.path}: bom.system: expected a list of {{key, qty, for}}")
    out = []
    for i, entry in enumerate(listed):
        item = Node(entry, f"bom.system[{i}]", str(params.path))
        qty = item.raw("qty")
        if qty == "boards":
            qty = boards
        elif isinstance(qty, bool) or not isinstance(qty, int) or qty < 1:
            raise item.fail("qty", f"expected a whole number >= 1 or `boards`, got {qty!r}")
        out.append((item.text("key"), qty, item.text("for")))
    return out
