# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Access to KiCad's installed symbol libraries: flattened symbols and their pin positions."""
import copy
import functools
import os

from sexpr import Sym, find, find1, parse

SYMBOL_DIR = os.environ.get("KICAD9_SYMBOL_DIR", "/usr/share/kicad/symbols")
FOOTPRINT_DIR = os.environ.get("KICAD9_FOOTPRINT_DIR", "/usr/share/kicad/footprints")

_texts = {}
_symbols = {}


def _library_text(name):
    if name not in _texts:
        path = os.path.join(SYMBOL_DIR, name + ".kicad_sym")
        if not os.path.exists(path):
            raise FileNotFoundError(f"symbol library {name!r} not found at {path} (is kicad-symbols installed?)")
        with open(path, encoding="utf-8") as f:
            _texts[name] = (path, f.read())
    return _texts[name]


def _raw_symbol(lib, name):
    """Parse just one top-level symbol: the big libraries (MCUs) take seconds to parse whole."""
    key = (lib, name)
    if key not in _symbols:
        path, text = _library_text(lib)
        start = text.find(f'\n\t(symbol "{name}"\n')
        if start < 0:
            raise KeyError(f"symbol {name!r} not in library {lib!r} ({path})")
        end = text.find("\n\t(symbol \"", start + 1)
        if end < 0:
            end = text.rindex("\n)")
        line = text.count("\n", 0, start) + 2
        _symbols[key] = parse(text[start:end], f"{path} (symbol {name} at line {line})")
    return _symbols[key]


@functools.lru_cache(maxsize=None)
def _flattened(lib_id):
    return flattened_symbol_uncached(lib_id)


def flattened_symbol(lib_id):
    return copy.deepcopy(_flattened(lib_id))


def flattened_symbol_uncached(lib_id):
    """The symbol as KiCad embeds it in a schematic's lib_symbols: derived symbols resolved, named lib:name."""
    lib, name = lib_id.split(":", 1)
    sym = copy.deepcopy(_raw_symbol(lib, name))
    ext = find1(sym, "extends")
    if ext:
        parent = flattened_symbol(f"{lib}:{ext[1]}")
        parent_name = ext[1]
        own_props = {p[1]: p for p in find(sym, "property")}
        out = [Sym("symbol"), lib_id]
        for item in parent[2:]:
            if isinstance(item, list) and item and item[0] == "property" and item[1] in own_props:
                out.append(own_props.pop(item[1]))
            elif isinstance(item, list) and item and item[0] == "symbol":
                unit = copy.deepcopy(item)
                unit[1] = name + unit[1][len(parent_name.split(":", 1)[-1]):]
                out.append(unit)
            else:
                out.append(item)
        # properties only the derived symbol has go before the unit definitions
        first_unit = next(i for i, x in enumerate(out) if isinstance(x, list) and x and x[0] == "symbol")
        for p in own_props.values():
            out.insert(first_unit, p)
            first_unit += 1
        return out
    sym[1] = lib_id
    return sym


@functools.lru_cache(maxsize=None)
def _pins(lib_id):
    return tuple(_pin_list(lib_id))


def pins(lib_id):
    return list(_pins(lib_id))


def _pin_list(lib_id):
    """[(number, name, electrical type, x, y, angle)] in symbol coordinates (y up)."""
    return [pin for _unit, pin in _unit_pin_list(lib_id)]


def _unit_pin_list(lib_id):
    """[(unit, pin)] over the symbol's unit definitions, named NAME_<unit>_<body style>; unit 0 is
    common to all units. Body style 2 (De Morgan alternative) repeats style 1's pins and is skipped."""
    out = []
    for unit in find(flattened_symbol(lib_id), "symbol"):
        number, style = (int(v) for v in unit[1].rsplit("_", 2)[1:])
        if style > 1:
            continue
        for p in find(unit, "pin"):
            at = find1(p, "at")
            out.append((number, (str(find1(p, "number")[1]), str(find1(p, "name")[1]), str(p[1]),
                                 float(at[1]), float(at[2]), int(at[3]) if len(at) > 3 else 0)))
    return out


@functools.lru_cache(maxsize=None)
def _units(lib_id):
    listed = _unit_pin_list(lib_id)
    numbers = sorted({u for u, _ in listed} - {0}) or [1]
    return tuple((n, tuple(pin for u, pin in listed if u in (0, n))) for n in numbers)


def units(lib_id):
    """{unit number: pins of that unit} (pins as in pins()); a single-unit symbol has unit 1 only.
    Each unit of a multi-unit symbol (a gate, or the supply pins) is placed as its own instance."""
    return {n: list(p) for n, p in _units(lib_id)}
