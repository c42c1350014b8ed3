# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The holding-brake channels of the motor board (revision D) against the brakes the head carries.

Each motor channel n has a brake output: a low-side N-MOSFET whose drain takes the coil's return (net
M<n>_BRAKE_N), its source on GND and its gate on an MCU pin (M<n>_BRAKE) pulled down to GND, a flyback
diode from the coil's return to +12V, and a 2-pin header with +12V and the return. Every brake of the
parameter file (drives.<joint>.brake) is switched by the channel of the board axis its joint is on, and its
coil current (coil power / coil voltage) must be within that channel's ratings from the catalog: the
MOSFET's continuous drain current, the diode's forward current and the header's contact rating. The coil
voltage must be the board's 12 V, and the MOSFET's and the diode's voltage ratings must stay above it.
"""
from __future__ import annotations

from dataclasses import dataclass

BOARD_SUPPLY_V = 12.0


@dataclass(frozen=True)
class Channel:
    axis: int            # 0 or 1, the board axis (motor channel n = axis + 1)
    switch: object       # design.Part
    diode: object
    pulldown: object
    header: object


def _nets(part):
    return {n for n in part.pins.values() if n}


def channel(parts, axis):
    """The brake channel of board axis `axis`; ValueError naming what is missing or miswired."""
    m = f"M{axis + 1}_"
    gate, ret = m + "BRAKE", m + "BRAKE_N"
    switch = [p for p in parts if p.lib_id.startswith("Transistor_FET:") and p.pins.get("3") == ret]
    diode = [p for p in parts if p.lib_id == "Device:D" and p.pins == {"1": "+12V", "2": ret}]
    pulldown = [p for p in parts if p.lib_id == "Device:R" and _nets(p) == {gate, "GND"}]
    header = [p for p in parts if p.ref.startswith("J") and p.pins == {"1": "+12V", "2": ret}]
    problems = []
    if len(switch) != 1:
        problems.append(f"{len(switch)} MOSFETs with their drain on {ret} (want 1)")
    elif switch[0].pins.get("1") != gate or switch[0].pins.get("2") != "GND":
        problems.append(f"{switch[0].ref}: gate on {switch[0].pins.get('1')}, source on {switch[0].pins.get('2')} "
                        f"(want {gate}, GND)")
    if len(diode) != 1:
        problems.append(f"{len(diode)} flyback diodes from {ret} to +12V (want 1)")
    if len(pulldown) != 1:
        problems.append(f"{len(pulldown)} pull-downs from {gate} to GND (want 1: the brake must hold while the MCU "
                        "is in reset)")
    if len(header) != 1:
        problems.append(f"{len(header)} headers with +12V on pin 1 and {ret} on pin 2 (want 1)")
    mcu = [p for p in parts if p.ref == "U1" and gate in p.pins.values()]
    if not mcu:
        problems.append(f"no MCU pin drives {gate}")
    if problems:
        raise ValueError(f"brake channel of axis {axis}: " + "; ".join(problems))
    return Channel(axis, switch[0], diode[0], pulldown[0], header[0])


def brakes(params):
    """{joint: (coil current A, coil voltage V, brake part)} for every braked drive of the parameter file."""
    out = {}
    for joint, drive in params["drives"].items():
        key = drive.get("brake")
        if not key:
            continue
        spec = params["purchased"][key]
        volts, watts = float(spec["voltage"]), float(spec["power_W"])
        out[joint] = (watts / volts, volts, key)
    return out


def board_axis(params, joint):
    """(board name, axis) of the board axis that drives `joint`, or None."""
    for board in params["motor_control"]["boards"]:
        if joint in board["axes"]:
            return board["name"], board["axes"].index(joint)
    return None


def _rating(catalog_entries, by_mpn, part, field):
    key = by_mpn.get(part.mpn.casefold())
    if key is None or field not in catalog_entries[key]:
        raise ValueError(f"{part.ref} ({part.mpn}): no {field} in the catalog")
    return float(catalog_entries[key][field])


def check(params, parts, catalog):
    """([problem], [joint checked]) for every brake of the parameter file. catalog: (entries, mpn -> key)."""
    entries, by_mpn = catalog
    problems, checked = [], []
    for joint, (amps, volts, key) in sorted(brakes(params).items()):
        where = board_axis(params, joint)
        if where is None:
            problems.append(f"{joint}: its brake {key} is on no board axis (motor_control.boards)")
            continue
        board, axis = where
        ch = channel(parts, axis)
        if abs(volts - BOARD_SUPPLY_V) > 1e-9:
            problems.append(f"{joint}: brake {key} has a {volts:g} V coil; the board switches its {BOARD_SUPPLY_V:g} V "
                            "supply")
        for part, field, what in ((ch.switch, "current_rating", "switch"), (ch.diode, "current_rating", "flyback diode"),
                                  (ch.header, "current_rating", "header contact")):
            rated = _rating(entries, by_mpn, part, field)
            if amps > rated:
                problems.append(f"{joint} ({board} axis {axis}): brake {key} draws {amps:.3f} A, over the {what} "
                                f"{part.ref} ({part.mpn}) rating of {rated:g} A")
        for part, what in ((ch.switch, "switch"), (ch.diode, "flyback diode")):
            rated = _rating(entries, by_mpn, part, "voltage_rating")
            if rated <= volts:
                problems.append(f"{joint} ({board} axis {axis}): the {what} {part.ref} ({part.mpn}) is rated "
                                f"{rated:g} V, not above the coil's {volts:g} V")
        checked.append(joint)
    return problems, checked
