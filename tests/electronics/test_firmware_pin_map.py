# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The firmware's pin map (stm32/board_pins.h) names the pins the board really wires.

Each `#define PIN_<NET> <n>u  // P<port><n> ...` is checked three ways: the number matches the port pin in its
comment, the MCU symbol in the committed schematic puts that port pin on a package pin, and the board design
connects that package pin to <NET>. Every signal net of the MCU that firmware drives must have a define, so a
pin moved on the board (as M2_AEA_CS moved from PB5 to PA5 in revision C) fails here until the firmware follows.
"""
import re

import pytest

import design
from conftest import ROOT, SCH

PINS_H = ROOT / "hardware" / "electronics" / "firmware" / "stm32" / "board_pins.h"
MCU_SYMBOL = "MCU_ST_STM32G4:STM32G431KBTx"
# Nets the firmware does not address by pin: power, the crystal (RCC takes it), reset, SWD and BOOT0 (the core).
# (BOOT0, PB8, is the status LED's pin once the part has started: the firmware addresses it.)
NOT_FIRMWARE_PINS = {"+3V3", "GND", "HSE_IN", "HSE_OUT", "NRST", "SWDIO", "SWCLK"}
DEFINE = re.compile(r"#define PIN_(\w+)\s+(\d+)u\s*//\s*P([A-G])(\d+)\b")


def pin_defines(text):
    """{net: (port letter, pin index)} from board_pins.h; a define whose value and comment disagree fails."""
    found = {}
    for net, value, port, index in DEFINE.findall(text):
        assert int(value) == int(index), f"board_pins.h: PIN_{net} is {value} but its comment says P{port}{index}"
        found[net] = (port, int(index))
    return found


def package_pins_of_symbol(schematic_text, symbol):
    """{"PA5": "10", ...}: the MCU symbol's port pins and their package pin numbers, from the schematic."""
    start = schematic_text.find(f'(symbol "{symbol}"')
    assert start >= 0, f"{SCH.name}: no embedded symbol {symbol}"
    # The symbol's units follow as nested (symbol "<name>_1_1"); its body ends at the next library symbol.
    next_symbol = re.compile(r'\(symbol "(?!' + re.escape(symbol.split(":")[1]) + r'_)')
    match = next_symbol.search(schematic_text, start + 1)
    body = schematic_text[start:match.start() if match else len(schematic_text)]
    pins = re.findall(r'\(pin \w+ \w+.*?\(name "(P[A-G]\d+)[^"]*".*?\(number "(\d+)"', body, re.S)
    return {name: number for name, number in pins}


def mcu_nets(parts):
    mcu = [p for p in parts if p.lib_id == MCU_SYMBOL]
    assert len(mcu) == 1, f"expected one {MCU_SYMBOL} in the design, found {len(mcu)}"
    return mcu[0].pins


def check_pin_map(defines, package_pins, nets):
    errors = []
    for net, (port, index) in sorted(defines.items()):
        number = package_pins.get(f"P{port}{index}")
        if number is None:
            errors.append(f"PIN_{net}: P{port}{index} is not a pin of the LQFP-32 package")
        elif nets.get(number) != net:
            errors.append(f"PIN_{net}: P{port}{index} (package pin {number}) carries {nets.get(number)!r} on the board")
    wired = {net for net in nets.values() if isinstance(net, str)} - NOT_FIRMWARE_PINS
    for net in sorted(wired - set(defines)):
        errors.append(f"board net {net} reaches the MCU but board_pins.h has no PIN_{net}")
    return errors


def test_firmware_pins_match_the_board():
    errors = check_pin_map(pin_defines(PINS_H.read_text()), package_pins_of_symbol(SCH.read_text(), MCU_SYMBOL),
                           mcu_nets(design.parts()))
    assert not errors, "\n".join(errors)


def test_a_revision_b_pin_map_is_refused():
    """Revision B's map put M2_AEA_CS on PB5 (now brake 1's gate): the check must name it."""
    rev_b = PINS_H.read_text().replace("#define PIN_M2_AEA_CS 5u  // PA5", "#define PIN_M2_AEA_CS 5u  // PB5")
    errors = check_pin_map(pin_defines(rev_b), package_pins_of_symbol(SCH.read_text(), MCU_SYMBOL),
                           mcu_nets(design.parts()))
    assert any("PIN_M2_AEA_CS: PB5 (package pin 28) carries 'M1_BRAKE'" in e for e in errors), errors


def test_a_revision_c_pin_map_is_refused():
    """Revision C's map drove the LED on PA4 and MOSI on PB5, the pins that switch the brakes since rev D: a
    firmware that still blinks PA4 would release brake 2 twice a second."""
    rev_c = re.sub(r"#define PIN_M2_BRAKE .*\n", "#define PIN_LED 4u        // PA4  status LED\n", PINS_H.read_text())
    rev_c = re.sub(r"#define PIN_M1_BRAKE .*\n(//.*\n|\s+//.*\n)?", "#define PIN_AEA_MOSI 5u   // PB5  SPI1_MOSI\n", rev_c)
    errors = check_pin_map(pin_defines(rev_c), package_pins_of_symbol(SCH.read_text(), MCU_SYMBOL),
                           mcu_nets(design.parts()))
    assert any("PIN_LED: PA4 (package pin 9) carries 'M2_BRAKE'" in e for e in errors), errors
    assert any("PIN_AEA_MOSI: PB5 (package pin 28) carries 'M1_BRAKE'" in e for e in errors), errors
    assert any("no PIN_M1_BRAKE" in e for e in errors) and any("no PIN_M2_BRAKE" in e for e in errors), errors


@pytest.mark.parametrize("line", ["#define PIN_LED 5u        // PA4  status LED"])
def test_a_define_that_disagrees_with_its_comment_is_refused(line):
    with pytest.raises(AssertionError, match="PIN_LED is 5 but its comment says PA4"):
        pin_defines(line)
