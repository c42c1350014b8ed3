# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Read a KiCad board BOM (CSV with the columns Reference, Value, Footprint, MPN, Qty)."""
from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

REQUIRED = ("Reference", "Value", "Footprint", "MPN", "Qty")


class BoardBomError(ValueError):
    pass


@dataclass(frozen=True)
class BoardLine:
    source: str       # file:line
    references: str
    value: str
    footprint: str
    mpn: str
    quantity: int


def read(path: Path) -> list[BoardLine]:
    try:
        text = path.read_text(encoding="utf-8-sig")
    except OSError as exc:
        raise BoardBomError(f"{path}: cannot read: {exc.strerror}") from None
    except UnicodeDecodeError as exc:
        raise BoardBomError(f"{path}: byte {exc.start}: not UTF-8") from None
    rows = list(csv.reader(text.splitlines()))
    if not rows:
        raise BoardBomError(f"{path}: empty file, expected a header {','.join(REQUIRED)}")
    header = [h.strip() for h in rows[0]]
    missing = [c for c in REQUIRED if c not in header]
    if missing:
        raise BoardBomError(f"{path}:1: header lacks column(s) {', '.join(missing)} (has {', '.join(header)})")
    col = {name: header.index(name) for name in REQUIRED}
    lines = []
    for number, row in enumerate(rows[1:], start=2):
        if not any(cell.strip() for cell in row):
            continue
        if len(row) < len(header):
            raise BoardBomError(f"{path}:{number}: {len(row)} fields, the header has {len(header)}")
        cell = {name: row[i].strip() for name, i in col.items()}
        if not cell["MPN"]:
            raise BoardBomError(f"{path}:{number}: {cell['Reference'] or 'line'} has no MPN")
        try:
            quantity = int(cell["Qty"])
        except ValueError:
            raise BoardBomError(f"{path}:{number}: Qty {cell['Qty']!r} is not a whole number") from None
        if quantity < 1:
            raise BoardBomError(f"{path}:{number}: Qty must be >= 1, got {quantity}")
        lines.append(BoardLine(f"{path.name}:{number}", cell["Reference"], cell["Value"], cell["Footprint"],
                               cell["MPN"], quantity))
    return lines
