# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The purchased-parts catalog (hardware/bom/catalog.yaml), validated on load."""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import yaml

from robogene_head_model import strict_yaml

DEFAULT_PATH = Path(__file__).resolve().parents[1] / "catalog.yaml"
FIELDS = ("description", "manufacturer", "mpn", "supplier", "datasheet", "breaks")


class CatalogError(ValueError):
    pass


@dataclass(frozen=True)
class Item:
    key: str
    description: str
    manufacturer: str
    mpn: str
    supplier: str
    datasheet: str
    breaks: tuple[tuple[int, float], ...]   # ascending minimum quantities, the first is 1
    note: str = ""
    unit: str = "pcs"    # pcs, or m for parts bought by length (wire)

    def unit_price(self, quantity: int) -> float:
        """Unit price when ordering `quantity` pieces: the largest break not above it."""
        if quantity < 1:
            raise ValueError(f"{self.key}: quantity must be >= 1, got {quantity}")
        price = self.breaks[0][1]
        for minimum, value in self.breaks:
            if quantity >= minimum:
                price = value
        return price


@dataclass(frozen=True)
class Catalog:
    path: Path
    currency: str
    items: dict[str, Item]

    def by_mpn(self) -> dict[str, Item]:
        return {item.mpn.casefold(): item for item in self.items.values()}

    def get(self, key: str, needed_by: str) -> Item:
        if key not in self.items:
            raise CatalogError(f"{self.path}: no entry for {key!r} (needed by {needed_by}); add it under parts: "
                               f"with {', '.join(FIELDS)}")
        return self.items[key]


def load(path: Path | str | None = None) -> Catalog:
    path = Path(path) if path else DEFAULT_PATH
    try:
        data = strict_yaml.load(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise CatalogError(f"{path}: cannot read: {exc.strerror}") from None
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark
        raise CatalogError(f"{path}:{mark.line + 1}:{mark.column + 1}: YAML error: {exc.problem}") from None
    if not isinstance(data, dict) or not isinstance(data.get("parts"), dict):
        raise CatalogError(f"{path}: expected a mapping with a 'parts' mapping")
    currency = data.get("currency")
    if not isinstance(currency, str) or not re.fullmatch(r"[A-Z]{3}", currency):
        raise CatalogError(f"{path}: currency: expected an ISO 4217 code like EUR, got {currency!r}")
    items = {}
    for key, entry in data["parts"].items():
        where = f"{path}: parts.{key}"
        if not isinstance(entry, dict):
            raise CatalogError(f"{where}: expected a mapping")
        for field in FIELDS:
            if field not in entry:
                raise CatalogError(f"{where}.{field}: missing")
        for field in FIELDS[:-2]:
            if not isinstance(entry[field], str) or not entry[field].strip():
                raise CatalogError(f"{where}.{field}: expected a non-empty string")
        generic = entry["manufacturer"].strip().lower().startswith("generic")
        if not (generic and entry["datasheet"] == "") and not (
                isinstance(entry["datasheet"], str) and re.fullmatch(r"https://[^\s/]+\.[^\s/]+/\S*", entry["datasheet"])):
            raise CatalogError(f"{where}.datasheet: expected an https:// link (only generic parts may leave it empty), "
                               f"got {entry['datasheet']!r}")
        breaks = entry["breaks"]
        if not isinstance(breaks, list) or not breaks:
            raise CatalogError(f"{where}.breaks: expected a list of [minimum quantity, unit price]")
        parsed = []
        for i, b in enumerate(breaks):
            if (not isinstance(b, list) or len(b) != 2 or isinstance(b[0], bool) or not isinstance(b[0], int)
                    or isinstance(b[1], bool) or not isinstance(b[1], (int, float)) or b[0] < 1 or b[1] <= 0):
                raise CatalogError(f"{where}.breaks[{i}]: expected [minimum quantity >= 1, unit price > 0], got {b!r}")
            parsed.append((b[0], float(b[1])))
        if parsed[0][0] != 1:
            raise CatalogError(f"{where}.breaks[0]: the first break must start at quantity 1")
        if any(a[0] >= b[0] for a, b in zip(parsed, parsed[1:])):
            raise CatalogError(f"{where}.breaks: minimum quantities must increase")
        unit = entry.get("unit", "pcs")
        if unit not in ("pcs", "m"):
            raise CatalogError(f"{where}.unit: expected pcs or m, got {unit!r}")
        items[key] = Item(key, entry["description"].strip(), entry["manufacturer"].strip(), entry["mpn"].strip(),
                          entry["supplier"].strip(), entry["datasheet"], tuple(parsed), str(entry.get("note", "")), unit)
    mpns = {}
    for item in items.values():
        other = mpns.setdefault(item.mpn.casefold(), item.key)
        if other != item.key:
            raise CatalogError(f"{path}: parts.{item.key}.mpn: {item.mpn!r} is also the MPN of parts.{other}")
    return Catalog(path, currency, items)
