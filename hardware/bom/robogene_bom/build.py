# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Write the head's BOM files (CSV for ordering, made-parts CSV, Markdown, HTML) into one folder."""
from __future__ import annotations

from pathlib import Path

from . import catalog as catalog_mod
from . import collect, render


def write_package(params, parts, board_boms: list[Path], out: Path, batch: int | None = None,
                  catalog_path: Path | None = None) -> collect.Bom:
    from robogene_head.parts import mounts

    batch = batch if batch is not None else int(params.root.node("bom").num("batch", positive=True))
    if batch < 1:
        raise ValueError(f"batch must be >= 1, got {batch}")
    catalog = catalog_mod.load(catalog_path)
    bom = collect.collect(parts, mounts.belts(params), board_boms, catalog)
    out.mkdir(parents=True, exist_ok=True)
    name = params.root.text("name")
    (out / f"{name}-bom.csv").write_text(render.to_csv(bom, batch))
    (out / f"{name}-made-parts.csv").write_text(render.made_csv(bom, batch))
    (out / f"{name}-bom.md").write_text(render.to_markdown(bom, batch))
    (out / f"{name}-bom.html").write_text(render.to_html(bom, batch, f"Robogene head rev {params.root['revision']}: "
                                                                     f"bill of materials"))
    return bom
