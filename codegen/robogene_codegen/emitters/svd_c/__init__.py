# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Register definitions for the motor-board firmware from a CMSIS-SVD device description.

Reads hardware/electronics/firmware/stm32/*.svd (device, peripherals with baseAddress and
derivedFrom, registers with addressOffset, fields with bitOffset/bitWidth) and writes one C header
per file, <device>_regs.h (into the folder the manifest names): <PERIPH>_BASE, <PERIPH>_<REG> as a volatile lvalue and its _OFFSET, and for the peripheral that
defines a layout <PERIPH>_<REG>_<FIELD>_Pos / _Msk. A derived peripheral gets its base, its
registers and its parent's field macros under its own name. Output is sorted by the file's own
order, so it is byte-identical on every run.
"""
from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

from ..common import line_comment_header

SVD_DIR = "hardware/electronics/firmware/stm32"


class SvdError(ValueError):
    pass


def _int(text: str | None, where: str) -> int:
    if text is None:
        raise SvdError(f"{where}: missing")
    try:
        return int(text.strip(), 0)
    except ValueError:
        raise SvdError(f"{where}: {text.strip()!r} is not a number") from None


def _text(node: ET.Element, tag: str, where: str) -> str:
    child = node.find(tag)
    if child is None or not (child.text or "").strip():
        raise SvdError(f"{where}: <{tag}> missing")
    return child.text.strip()


def parse(path: Path) -> list[dict]:
    """[{name, base, registers: [{name, offset, fields: [(name, pos, width)]}], derived_from}]"""
    root = ET.parse(path).getroot()
    peripherals, by_name = [], {}
    for p in root.iter("peripheral"):
        name = _text(p, "name", f"{path.name}: peripheral")
        where = f"{path.name}: {name}"
        entry = {"name": name, "base": _int(p.findtext("baseAddress"), f"{where}.baseAddress"),
                 "derived_from": p.get("derivedFrom"), "registers": []}
        for r in p.iter("register"):
            rname = _text(r, "name", f"{where}: register")
            fields = []
            for f in r.iter("field"):
                fname = _text(f, "name", f"{where}.{rname}: field")
                pos = _int(f.findtext("bitOffset"), f"{where}.{rname}.{fname}.bitOffset")
                width = _int(f.findtext("bitWidth"), f"{where}.{rname}.{fname}.bitWidth")
                if pos + width > 32:
                    raise SvdError(f"{where}.{rname}.{fname}: bits {pos}..{pos + width - 1} exceed the 32-bit register")
                fields.append((fname, pos, width))
            entry["registers"].append({"name": rname, "offset": _int(r.findtext("addressOffset"), f"{where}.{rname}"),
                                       "fields": fields})
        if name in by_name:
            raise SvdError(f"{path.name}: peripheral {name} defined twice")
        by_name[name] = entry
        peripherals.append(entry)
    for entry in peripherals:
        parent = entry["derived_from"]
        if parent:
            if parent not in by_name:
                raise SvdError(f"{path.name}: {entry['name']} derives from unknown {parent}")
            if entry["registers"]:
                raise SvdError(f"{path.name}: {entry['name']} derives from {parent} and lists registers too")
            entry["registers"] = by_name[parent]["registers"]
    return peripherals


def render(path: Path, source: str) -> str:
    guard = path.stem.upper() + "_REGS_H"
    lines = [line_comment_header("//", "BSD-3-Clause", [source], change="the SVD file").rstrip("\n"), "//",
             f"// Register access for {path.stem.upper()}: <PERIPH>_<REG> is the register (volatile uint32_t),",
             "// <PERIPH>_<REG>_OFFSET its offset in the peripheral, <PERIPH>_<REG>_<FIELD>_Pos and _Msk its fields.",
             f"#ifndef {guard}", f"#define {guard}", "", "#include <stdint.h>", "",
             "#define RG_REG32(address) (*(volatile uint32_t *)(uintptr_t)(address))"]
    for p in parse(path):
        n = p["name"]
        lines += ["", f"// {n}" + (f" (layout of {p['derived_from']})" if p["derived_from"] else ""),
                  f"#define {n}_BASE 0x{p['base']:08X}u"]
        for r in p["registers"]:
            lines.append(f"#define {n}_{r['name']}_OFFSET 0x{r['offset']:03X}u")
            lines.append(f"#define {n}_{r['name']} RG_REG32({n}_BASE + {n}_{r['name']}_OFFSET)")
            for fname, pos, width in r["fields"]:
                mask = ((1 << width) - 1) << pos
                lines.append(f"#define {n}_{r['name']}_{fname}_Pos {pos}u")
                lines.append(f"#define {n}_{r['name']}_{fname}_Msk 0x{mask:08X}u")
    lines += ["", f"#endif  // {guard}", ""]
    return "\n".join(lines)


def emit(root: Path) -> dict[str, str]:
    """One header per device description in the repository's SVD folder."""
    out = {}
    for path in sorted((root / SVD_DIR).glob("*.svd")):
        out[f"{path.stem}_regs.h"] = render(path, f"{SVD_DIR}/{path.name}")
    return out
