# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Access to KiCad's installed symbol libraries: flattened symbols and their pin positions."""
import copy
import os

from sexpr import Sym, find, find1, parse

SYMBOL_DIR = os.environ.get("KICAD9_SYMBOL_DIR", "/usr/share/kicad/symbols")
FOOTPRINT_DIR = os.environ.get("KICAD9_FOOTPRINT_DIR", "/usr/share/kicad/footprints")

_libs = {}


def _library(name):
    if name not in _libs:
        path = os.path.join(SYMBOL_DIR, name + ".kicad_sym")
        if not os.path.exists(path):
            raise FileNotFoundError(f"symbol library {name!r} not found at {path} (is kicad-symbols installed?)")
        with open(path, encoding="utf-8") as f:
            _libs[name] = parse(f.read(), path)
    return _libs[name]


def _raw_symbol(lib, name):
    for s in find(_library(lib), "symbol"):
        if s[1] == name:
            return s
    raise KeyError(f"symbol {name!r} not in library {lib!r}")


def flattened_symbol(lib_id):
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


def pins(lib_id):
    """[(number, name, electrical type, x, y, angle)] in symbol coordinates (y up)."""
    out = []
    for unit in find(flattened_symbol(lib_id), "symbol"):
        for p in find(unit, "pin"):
            at = find1(p, "at")
            out.append((str(find1(p, "number")[1]), str(find1(p, "name")[1]), str(p[1]),
                        float(at[1]), float(at[2]), int(at[3]) if len(at) > 3 else 0))
    return out
