# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The quadrature encoders (5 V supply, outputs up to 5 V) reach the MCU only through a buffer that runs
on 3.3 V and tolerates 5 V on its inputs with or without supply, checked on the design's netlist."""
import design
from kicad_lib import units

MCU = "U1"
BUFFER_SYMBOLS = {"74xGxx:74LVC2G17"}  # 3.3 V supply, 5.5 V-tolerant Schmitt inputs, Ioff
# timer encoder-mode pins the firmware uses: motor 1 on TIM2 (PA0/PA1), motor 2 on TIM4 (PB6/PB7)
MCU_PINS = {"M1_QA": "5", "M1_QB": "6", "M2_QA": "29", "M2_QB": "30"}


def _parts():
    return {p.ref: p for p in design.parts()}


def _pads_on(net, parts):
    return [(ref, pin) for ref, p in parts.items() for pin, n in p.pins.items() if n == net]


def _buffer_paths(parts):
    """(input net, output net, supply net) for every gate of every buffer part."""
    paths = []
    for p in parts.values():
        if p.lib_id not in BUFFER_SYMBOLS:
            continue
        unit_pins = units(p.lib_id)
        supply = next(p.pins[num] for pins in unit_pins.values() for num, name, *_ in pins if name == "VCC")
        for pins in unit_pins.values():
            ins = [num for num, _, etype, *_ in pins if etype == "input"]
            outs = [num for num, _, etype, *_ in pins if etype == "output"]
            if ins and outs:
                paths.append((p.pins[ins[0]], p.pins[outs[0]], supply))
    return paths


def _encoder_signal_nets(parts):
    nets = []
    for p in parts.values():
        if p.value == "QENC":
            nets += [n for n in p.pins.values() if n and n not in design.POWER_NETS]
    return nets


def test_every_quadrature_encoder_signal_is_buffered_before_the_mcu():
    parts = _parts()
    signals = _encoder_signal_nets(parts)
    assert len(signals) == 4, f"two connectors with A and B each, found {signals}"
    paths = {src: (out, supply) for src, out, supply in _buffer_paths(parts)}
    for net in signals:
        on_mcu = [pin for ref, pin in _pads_on(net, parts) if ref == MCU]
        assert not on_mcu, f"encoder net {net} goes straight into {MCU} pin(s) {on_mcu}"
        assert net in paths, f"encoder net {net} reaches no buffer input ({sorted(BUFFER_SYMBOLS)})"
        out, supply = paths[net]
        assert supply == "+3V3", f"the buffer taking {net} runs on {supply}, not +3V3"
        assert [pin for ref, pin in _pads_on(out, parts) if ref == MCU] == [MCU_PINS[out]], \
            f"buffered {net} -> {out} must drive {MCU} pin {MCU_PINS[out]}"


def test_each_buffer_is_decoupled_and_its_inputs_are_held_when_unplugged():
    parts = _parts()
    for p in parts.values():
        if p.lib_id not in BUFFER_SYMBOLS:
            continue
        caps = [c for c in parts.values() if c.lib_id == "Device:C" and set(c.pins.values()) == {"+3V3", "GND"}
                and c.block == p.block and c.value == "100n"]
        assert caps, f"{p.ref} has no 100 nF decoupling capacitor in its block {p.block}"
    for net in _encoder_signal_nets(parts):
        pulls = [r.ref for r in parts.values() if r.lib_id == "Device:R" and set(r.pins.values()) == {net, "GND"}]
        assert len(pulls) == 1, f"{net}: expected one pull-down to GND, found {pulls}"
