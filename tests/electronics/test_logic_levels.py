# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Every digital net's driver meets its receivers' input thresholds (catalog data, worst-case rails), and the
absolute encoders get every SPI input they need (rev B drove the 5 V AS5048A's CLK and CS at 3.3 V, below its
3.5 V VIH, and had no MOSI)."""
import copy
import dataclasses

import pytest

import design
import logic_levels
from kicad_lib import pins


def _parts():
    return design.parts()


def test_every_digital_net_meets_its_receivers_thresholds():
    problems, checked = logic_levels.check(_parts(), pins)
    assert problems == [], "\n".join(map(str, problems))
    # the nets the review named are among the checked ones, each with its encoder-side receiver or driver
    for net in ("AEA_CLK_5V", "M1_AEA_CS_5V", "M2_AEA_CS_5V", "AEA_MOSI_5V", "AEA_CLK",
                "AEA_ENC_DO", "AEA_DO", "M1_ENC_A", "M1_QA", "M1_IN1", "CAN_TX", "CAN_RX", "M1_BRAKE", "M2_BRAKE"):
        assert net in checked, net


def test_the_absolute_encoders_get_every_spi_input():
    assert logic_levels.unwired_device_pins(_parts()) == []


def test_mosi_idles_high():
    """The AS5048A returns the angle for the command 0xFFFF: MOSI held high. Since rev D no MCU pin drives it
    (PB5 switches brake 1): the pull-up alone holds the level shifter's input high, and the shifter drives
    the encoders' MOSI."""
    parts = {p.ref: p for p in _parts()}
    pullups = [p for p in parts.values() if p.lib_id == "Device:R" and set(p.pins.values()) == {"AEA_MOSI", "+3V3"}]
    assert pullups, "no pull-up from AEA_MOSI to +3V3"
    on_net = sorted(p.ref for p in parts.values() if "AEA_MOSI" in p.pins.values())
    assert on_net == sorted([pullups[0].ref, "U12"]), on_net
    assert parts["U12"].pins["12"] == "AEA_MOSI" and parts["U12"].pins["11"] == "AEA_MOSI_5V"


def _rev_b_wiring(parts):
    """The rev B encoder wiring on the rev C part table: the MCU's 3.3 V outputs straight to the connector,
    no level shifter, no MOSI pin."""
    out = []
    for p in parts:
        if p.ref in ("U12", "C18", "R9", "R10", "R11"):
            continue
        if p.value == "AEA":
            pins_ = {k: (v[:-3] if v and v.endswith("_5V") else v) for k, v in p.pins.items() if k != "5"}
            ext = {k: v for k, v in p.extra["external"].items() if k != "5"}
            p = dataclasses.replace(p, pins=pins_, extra={"external": ext})
        out.append(p)
    return out


def test_the_check_fails_on_the_rev_b_wiring():
    problems, _ = logic_levels.check(_rev_b_wiring(_parts()), pins)
    failing = {p.net for p in problems}
    assert {"AEA_CLK", "M1_AEA_CS", "M2_AEA_CS"} <= failing, "\n".join(map(str, problems))
    assert any("VOH 2.73 V < VIH 3.67 V" in str(p) for p in problems), "\n".join(map(str, problems))
    assert ("J22", "ams-AS5048A", "MOSI") in logic_levels.unwired_device_pins(_rev_b_wiring(_parts()))


def test_level_expressions():
    assert logic_levels.evaluate("0.7*VDD", 5.0, "x") == pytest.approx(3.5)
    assert logic_levels.evaluate("VDD-0.4", 3.3, "x") == pytest.approx(2.9)
    assert logic_levels.evaluate("0.49*VDD+0.26", 3.3, "x") == pytest.approx(1.877)
    assert logic_levels.evaluate(2.0, None, "x") == 2.0
    with pytest.raises(logic_levels.LevelDataError, match="U1.5"):
        logic_levels.evaluate("VDD/2", 3.3, "U1.5")
    with pytest.raises(logic_levels.LevelDataError, match="no logic rail"):
        logic_levels.evaluate("0.7*VDD", None, "J12.2")


def test_missing_catalog_data_is_named():
    parts = copy.deepcopy(_parts())
    j22 = next(p for p in parts if p.ref == "J22")
    j22.extra["external"]["2"] = ("ams-AS5048A", "SCLK")
    with pytest.raises(logic_levels.LevelDataError, match=r"J22\.2.*AS5048A SCLK"):
        logic_levels.check(parts, pins)
