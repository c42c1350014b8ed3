# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The supply entry on the design's netlist: a reversed supply meets the reverse-polarity FET before any
diode (rev B put the TVS first: reversed, it conducted through the soldered fuse and blew it), and the board
passes the supply on to the next one through a second connector rated for the chain's current."""
import dataclasses

import yaml

import design
from conftest import ROOT
from test_copper_capacity import chain_amps

CATALOG = yaml.safe_load((ROOT / "hardware" / "bom" / "catalog.yaml").read_text())["parts"]
BY_MPN = {str(e["mpn"]).casefold(): e for e in CATALOG.values()}
SERIES_PASSIVES = ("Device:Fuse",)   # parts a reversed supply passes unchanged


def _parts():
    return {p.ref: p for p in design.parts()}


def _power_connectors(parts):
    return [p for p in parts.values() if p.lib_id.startswith("Connector") and set(p.pins.values()) == {"VIN_RAW", "GND"}]


def _input_side_nets(parts):
    """Nets a reversed supply reaches without passing a transistor: the connectors' positive pins and
    whatever the fuses join to them."""
    nets = {"VIN_RAW"}
    grew = True
    while grew:
        grew = False
        for p in parts.values():
            if p.lib_id in SERIES_PASSIVES and set(p.pins.values()) & nets and not set(p.pins.values()) <= nets:
                nets |= set(p.pins.values())
                grew = True
    return nets


def _diodes(parts):
    return [p for p in parts.values() if p.lib_id.startswith("Diode:") or p.lib_id.startswith("Device:D")]


def _diodes_before_the_fet(parts):
    exposed = _input_side_nets(parts)
    return [d.ref for d in _diodes(parts) if set(d.pins.values()) & exposed]


def test_no_diode_sits_before_the_reverse_polarity_fet():
    """Reversed, the input is negative against GND: any diode between an input-side net and GND (a TVS, a
    clamp) would conduct through the fuse."""
    parts = _parts()
    assert _diodes_before_the_fet(parts) == [], f"diodes on the unprotected input {sorted(_input_side_nets(parts))}"


def test_the_order_check_fails_on_rev_b_order():
    """A broken variant: the TVS back on the fuse's output, before the FET, as in rev B."""
    parts = _parts()
    parts["D1"] = dataclasses.replace(parts["D1"], pins={"1": "VIN_FUSED", "2": "GND"})
    assert _diodes_before_the_fet(parts) == ["D1"]


def test_the_fet_blocks_a_reversed_supply():
    """P-MOSFET with its drain on the input side and its source on +12V: its body diode conducts only with
    the right polarity; the gate is pulled to GND (on only when the supply is right) and clamped."""
    parts = _parts()
    q1 = parts["Q1"]
    assert q1.pins["5"] in _input_side_nets(parts)                    # drain (pad 5, the exposed pad)
    assert {q1.pins[n] for n in ("1", "2", "3")} == {"+12V"}          # source
    gate = q1.pins["4"]
    assert any(p.lib_id == "Device:R" and set(p.pins.values()) == {gate, "GND"} for p in parts.values())
    assert any(p.lib_id == "Device:D_Zener" and set(p.pins.values()) == {gate, "+12V"} for p in parts.values())
    tvs = [d for d in _diodes(parts) if "TVS" in d.description]
    assert tvs and all(set(d.pins.values()) == {"+12V", "GND"} for d in tvs), [d.pins for d in tvs]


def test_two_power_connectors_for_the_daisy_chain():
    connectors = _power_connectors(_parts())
    assert len(connectors) == 2, [c.ref for c in connectors]


def test_the_chain_check_fails_without_the_output_connector():
    parts = _parts()
    del parts["J5"]
    assert len(_power_connectors(parts)) == 1


def test_power_connectors_are_rated_for_the_chain_current():
    for c in _power_connectors(_parts()):
        rating = BY_MPN[c.mpn.casefold()].get("current_rating")
        assert rating is not None, f"{c.ref} ({c.mpn}): no current_rating in the catalog"
        assert rating >= chain_amps(), f"{c.ref}: {rating} A < chain {chain_amps():.2f} A"


def test_each_board_fuses_only_its_own_current():
    """The pass-through is on the fuse's input side, so a board's fuse never carries the next boards' current."""
    parts = _parts()
    fuse = next(p for p in parts.values() if p.lib_id == "Device:Fuse")
    assert fuse.pins["1"] == "VIN_RAW"
    assert all(c.pins["1"] == "VIN_RAW" for c in _power_connectors(parts))
