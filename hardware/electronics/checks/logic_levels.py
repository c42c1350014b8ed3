# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Logic levels of every digital net of the board, from the parts' data in the catalog.

For each net that joins a driving pin with a receiving pin (on the board, or on a device plugged into a
connector, as design.py's `extra["external"]` names it), the driver's worst-case output levels must meet
the receiver's worst-case input thresholds:  VOH(min) >= VIH  and  VOL(max) <= VIL. Levels given as a
fraction of a supply ("0.7*VDD", "VDD-0.4") are evaluated at that part's rail: outputs at the rail's low
limit, thresholds at its high limit.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import yaml

RAILS = {"+3V3": 3.3, "+5V": 5.0}   # nominal volts of the board's logic rails
RAIL_TOLERANCE = 0.05               # worst case either way (regulator accuracy, load steps, ripple)
CATALOG = Path(__file__).resolve().parents[2] / "bom" / "catalog.yaml"


class LevelDataError(ValueError):
    pass


@dataclass(frozen=True)
class Pin:
    where: str         # "U1.26 (PB3)" or "J12.2 -> ams-AS5048A CLK"
    role: str          # "driver" or "receiver"
    levels: dict       # vih/vil/voh/vol -> expression
    rail: str | None   # supply net for VDD-relative levels


@dataclass(frozen=True)
class Problem:
    net: str
    driver: str
    receiver: str
    text: str

    def __str__(self):
        return f"{self.net}: {self.driver} -> {self.receiver}: {self.text}"


def load_catalog(path=CATALOG):
    with open(path, encoding="utf-8") as f:
        parts = yaml.safe_load(f)["parts"]
    return parts, {str(e["mpn"]).casefold(): key for key, e in parts.items()}


def evaluate(expr, vdd, where):
    """A level: volts, or a linear expression in VDD: 'VDD', 'k*VDD', 'VDD-x', 'k*VDD+x', 'k*VDD-x'."""
    if isinstance(expr, (int, float)) and not isinstance(expr, bool):
        return float(expr)
    m = re.fullmatch(r"\s*(?:([\d.]+)\s*\*\s*)?VDD\s*(?:([+-])\s*([\d.]+))?\s*", str(expr))
    if not m:
        raise LevelDataError(f"{where}: level {expr!r} is neither volts nor a linear expression in VDD")
    if vdd is None:
        raise LevelDataError(f"{where}: level {expr!r} depends on VDD but the part has no logic rail")
    value = float(m.group(1) or 1) * vdd
    if m.group(3):
        value += float(m.group(3)) * (1 if m.group(2) == "+" else -1)
    return value


def _rail(part, pin_types):
    """The part's logic supply: the rail on its power-input pins."""
    rails = {part.pins.get(num) for num, (_, etype) in pin_types.items() if etype == "power_in"} & set(RAILS)
    return rails.pop() if len(rails) == 1 else None


def collect_pins(parts, pins_of, catalog=None):
    """net -> [Pin] for every pin whose part (or plugged-in device) has logic data in the catalog.
    pins_of(lib_id) -> [(number, name, electrical type, ...)] as kicad_lib.pins."""
    entries, by_mpn = catalog or load_catalog()
    nets = {}
    for part in parts:
        key = by_mpn.get(part.mpn.casefold()) if part.mpn else None
        logic = entries[key].get("logic") if key else None
        pin_types = {p[0]: (p[1], p[2]) for p in pins_of(part.lib_id)}
        if logic:
            rail = _rail(part, pin_types)
            for num, net in part.pins.items():
                if net is None or num not in pin_types:
                    continue
                name, etype = pin_types[num]
                levels = logic.get(name, logic.get("*"))
                if not levels or etype in ("power_in", "power_out", "passive", "no_connect"):
                    continue
                role = {"input": "receiver", "output": "driver", "tri_state": "driver",
                        "open_collector": "open-drain", "bidirectional": "bidirectional"}.get(etype)
                if role:
                    nets.setdefault(net, []).append(Pin(f"{part.ref}.{num} ({name})", role, levels, rail))
        for num, (device, device_pin) in part.extra.get("external", {}).items():
            net = part.pins.get(num)
            if device not in entries or device_pin not in (entries[device].get("logic") or {}):
                raise LevelDataError(f"{part.ref}.{num}: plugged-in {device} {device_pin} has no logic data "
                                     f"in {CATALOG.name}")
            levels = entries[device]["logic"][device_pin]
            rail = next((n for n in part.pins.values() if n in RAILS), None)
            role = "driver" if "voh" in levels else "receiver"
            nets.setdefault(net, []).append(Pin(f"{part.ref}.{num} -> {device} {device_pin}", role, levels, rail))
    return nets


def check(parts, pins_of, catalog=None):
    """[Problem] over every net with a driver and a receiver, and the nets that were checked."""
    problems, checked = [], []
    for net, pins in sorted(collect_pins(parts, pins_of, catalog).items(), key=lambda kv: str(kv[0])):
        if net is None:
            problems.extend(Problem("(unconnected)", "-", p.where, "a logic input of a plugged-in device is "
                                    "not wired to anything") for p in pins if p.role == "receiver")
            continue
        drivers = [p for p in pins if p.role == "driver"]
        # an MCU pin (bidirectional) drives a net that nothing else drives, and reads one that something does
        bidir = [p for p in pins if p.role == "bidirectional"]
        if drivers or any(p.role == "open-drain" for p in pins):
            receivers = [p for p in pins if p.role == "receiver"] + bidir
        else:
            drivers, receivers = bidir, [p for p in pins if p.role == "receiver"]
        if not drivers or not receivers:
            continue
        checked.append(net)
        for d in drivers:
            for r in receivers:
                problems += _compare(net, d, r)
    return problems, checked


def _compare(net, d, r):
    out = []
    d_vdd = RAILS[d.rail] * (1 - RAIL_TOLERANCE) if d.rail else None
    d_vdd_high = RAILS[d.rail] * (1 + RAIL_TOLERANCE) if d.rail else None
    r_vdd = RAILS[r.rail] * (1 + RAIL_TOLERANCE) if r.rail else None
    r_vdd_low = RAILS[r.rail] * (1 - RAIL_TOLERANCE) if r.rail else None
    for out_key, in_key in (("voh", "vih"), ("vol", "vil")):
        if out_key not in d.levels or in_key not in r.levels:
            raise LevelDataError(f"{net}: {d.where} has no {out_key} or {r.where} has no {in_key} in the catalog")
        if out_key == "voh":
            v_out, v_in = evaluate(d.levels["voh"], d_vdd, d.where), evaluate(r.levels["vih"], r_vdd, r.where)
            if v_out < v_in:
                out.append(Problem(net, d.where, r.where, f"VOH {v_out:.2f} V < VIH {v_in:.2f} V"))
        else:
            v_out, v_in = evaluate(d.levels["vol"], d_vdd_high, d.where), evaluate(r.levels["vil"], r_vdd_low, r.where)
            if v_out > v_in:
                out.append(Problem(net, d.where, r.where, f"VOL {v_out:.2f} V > VIL {v_in:.2f} V"))
    return out


def unwired_device_pins(parts, catalog=None):
    """Logic pins of a plugged-in device that its connector does not wire: [(connector, device, pin)]."""
    entries, _ = catalog or load_catalog()
    missing = []
    for part in parts:
        wired = {}
        for device, device_pin in part.extra.get("external", {}).values():
            wired.setdefault(device, set()).add(device_pin)
        for device, pins in wired.items():
            missing += [(part.ref, device, pin) for pin in sorted(set(entries[device].get("logic") or {}) - pins)]
    return missing
