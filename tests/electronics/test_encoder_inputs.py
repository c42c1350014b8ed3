# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The encoders (5 V supply, outputs up to 5 V) reach the MCU only through a buffer that runs on 3.3 V
and tolerates 5 V on its inputs with or without supply, checked on the design's netlist: the quadrature
encoders' A/B and the absolute encoders' SSI data output alike."""
import design
from kicad_lib import pins, units

MCU = "U1"
# 3.3 V supply, 5.5 V-tolerant Schmitt inputs, Ioff
BUFFER_SYMBOLS = {"74xGxx:74LVC2G17", "74xGxx:74LVC1G17"}
# Every MCU pin that reads an encoder, by pin number and port name: the timer encoder-mode pins the
# firmware uses (motor 1 on TIM2, PA0/PA1; motor 2 on TIM4, PB6/PB7) and SPI1's MISO (PB4), which reads
# the absolute encoders' SSI data.
MCU_ENCODER_INPUTS = {"5": "PA0", "6": "PA1", "29": "PB6", "30": "PB7", "27": "PB4"}
MCU_PINS = {"M1_QA": "5", "M1_QB": "6", "M2_QA": "29", "M2_QB": "30", "AEA_DO": "27"}
# the encoder connectors' output pins: quadrature A and B, absolute encoder DO
ENCODER_OUTPUTS = {"QENC": ("2", "3"), "AEA": ("4",)}


def _parts():
    return {p.ref: p for p in design.parts()}


def _pads_on(net, parts):
    return [(ref, pin) for ref, p in parts.items() for pin, n in p.pins.items() if n == net]


def _is_connector(part):
    return part.lib_id.split(":")[0] in ("Connector", "Connector_Generic")


def _buffer_gates(parts):
    """(ref, input pin, output pin, supply net) for every gate of every buffer part."""
    gates = []
    for p in parts.values():
        if p.lib_id not in BUFFER_SYMBOLS:
            continue
        unit_pins = units(p.lib_id)
        supply = next(p.pins[num] for pins in unit_pins.values() for num, name, *_ in pins if name == "VCC")
        for pins_ in unit_pins.values():
            ins = [num for num, _, etype, *_ in pins_ if etype == "input"]
            outs = [num for num, _, etype, *_ in pins_ if etype == "output"]
            if ins and outs:
                gates.append((p.ref, ins[0], outs[0], supply))
    return gates


def _buffer_paths(parts):
    """input net -> (output net, supply net) over every buffer gate."""
    return {parts[ref].pins[i]: (parts[ref].pins[o], supply) for ref, i, o, supply in _buffer_gates(parts)}


def _encoder_signal_nets(parts):
    nets = []
    for p in parts.values():
        for pin in ENCODER_OUTPUTS.get(p.value, ()):
            net = p.pins[pin]
            if net and net not in nets:
                nets.append(net)
    return nets


def test_the_mcu_pin_table_matches_the_symbol():
    names = {num: name for num, name, *_ in pins(_parts()[MCU].lib_id)}
    assert {num: names[num] for num in MCU_ENCODER_INPUTS} == MCU_ENCODER_INPUTS


def test_every_encoder_input_of_the_mcu_is_driven_by_a_3v3_buffer_output():
    """Each MCU pin that reads an encoder is on a net with exactly one other pad: the output of a buffer
    supplied from +3V3. No connector pin (the encoder itself, 5 V-supplied) ever shares that net."""
    parts = _parts()
    outputs = {(ref, o): supply for ref, _i, o, supply in _buffer_gates(parts)}
    for num, port in MCU_ENCODER_INPUTS.items():
        net = parts[MCU].pins.get(num)
        assert net, f"{MCU} pin {num} ({port}) reads an encoder but has no net"
        others = [(ref, pin) for ref, pin in _pads_on(net, parts) if ref != MCU]
        direct = [f"{ref} pin {pin}" for ref, pin in others if _is_connector(parts[ref])]
        assert not direct, f"{port} (net {net}) is driven straight from connector {', '.join(direct)}"
        drivers = [(ref, pin) for ref, pin in others if (ref, pin) in outputs]
        assert len(drivers) == 1 and others == drivers, \
            f"{port} (net {net}) must be driven by one buffer output and nothing else, found {others}"
        assert outputs[drivers[0]] == "+3V3", f"{port}: buffer {drivers[0][0]} runs on {outputs[drivers[0]]}, not +3V3"


def test_every_encoder_signal_is_buffered_before_the_mcu():
    parts = _parts()
    signals = _encoder_signal_nets(parts)
    assert len(signals) == 5, f"two quadrature connectors with A and B each and the absolute encoders' shared DO, found {signals}"
    paths = _buffer_paths(parts)
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
