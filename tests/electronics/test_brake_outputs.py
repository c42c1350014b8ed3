# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The board's holding-brake outputs (revision D): rev C had none, so the neck's power-off brakes could not be
released. Each motor channel has its switch, flyback diode, gate pull-down and header, and each brake of the
parameter file is within the ratings of the channel that switches it (coil current = coil power / 12 V)."""
import copy
import dataclasses

import pytest
import yaml

import brake_channels
import design
import logic_levels
from conftest import ROOT
from kicad_lib import pins

PARAMS = yaml.safe_load((ROOT / "hardware" / "head-parameters.yaml").read_text())


def _check(params=PARAMS, parts=None):
    return brake_channels.check(params, parts or design.parts(), logic_levels.load_catalog())


def test_both_axes_have_a_brake_channel():
    parts = design.parts()
    for axis in (0, 1):
        ch = brake_channels.channel(parts, axis)
        assert ch.switch.footprint == "Package_TO_SOT_SMD:SOT-23"
        assert ch.header.mpn == "B2B-PH-K-S(LF)(SN)"


def test_every_brake_is_within_its_channel_ratings():
    problems, checked = _check()
    assert problems == [], "\n".join(problems)
    assert checked == ["neck_pitch", "neck_roll"]
    currents = {j: a for j, (a, _, _) in brake_channels.brakes(PARAMS).items()}
    assert currents == pytest.approx({"neck_pitch": 0.25, "neck_roll": 2.0 / 12})


def _with_coil_power(watts, joint="neck_pitch"):
    params = copy.deepcopy(PARAMS)
    params["purchased"][params["drives"][joint]["brake"]]["power_W"] = watts
    return params


def test_a_coil_over_the_switch_rating_fails():
    problems, _ = _check(_with_coil_power(72.0))   # 6 A at 12 V, over the AO3400A's 4.7 A
    assert any("neck_pitch" in p and "switch Q30 (AO3400A)" in p for p in problems), problems


def test_a_coil_over_the_flyback_diode_rating_fails():
    problems, _ = _check(_with_coil_power(9.0, "neck_roll"))   # 0.75 A, over the MBR0540's 0.5 A
    assert any("neck_roll" in p and "flyback diode D40" in p for p in problems), problems
    assert not any("switch" in p for p in problems), problems


def test_a_24_volt_coil_fails():
    params = copy.deepcopy(PARAMS)
    params["purchased"][params["drives"]["neck_roll"]["brake"]]["voltage"] = 24
    problems, _ = _check(params)
    assert any("neck_roll" in p and "24 V coil" in p for p in problems), problems


def test_a_channel_without_its_gate_pulldown_fails():
    """Without the pull-down the gate floats while the MCU is in reset: the brake could release unpowered."""
    parts = [p for p in design.parts() if p.ref != "R33"]
    with pytest.raises(ValueError, match=r"axis 0: .*0 pull-downs from M1_BRAKE"):
        brake_channels.channel(parts, 0)


def test_a_channel_with_source_and_drain_swapped_fails():
    parts = [dataclasses.replace(p, pins={"1": "M2_BRAKE", "2": "M2_BRAKE_N", "3": "GND"}) if p.ref == "Q40" else p
             for p in design.parts()]
    with pytest.raises(ValueError, match=r"axis 1: 0 MOSFETs with their drain on M2_BRAKE_N"):
        brake_channels.channel(parts, 1)


def test_the_gates_meet_the_mosfet_levels():
    """The MCU drives each gate directly: its worst-case high (VDD - 0.4 V at 3.3 V - 5 %) is above the
    2.5 V at which the AO3400A's Rds(on) is specified."""
    problems, checked = logic_levels.check(design.parts(), pins)
    assert {"M1_BRAKE", "M2_BRAKE"} <= set(checked)
    assert not [p for p in problems if "BRAKE" in p.net]


def test_a_mosfet_needing_more_gate_voltage_fails_the_level_check():
    entries, by_mpn = logic_levels.load_catalog()
    entries = copy.deepcopy(entries)
    entries["aos-AO3400A"]["logic"]["G"]["vih"] = 4.5   # a standard-level MOSFET, Rds(on) specified at 4.5 V
    problems, _ = logic_levels.check(design.parts(), pins, (entries, by_mpn))
    assert {p.net for p in problems} == {"M1_BRAKE", "M2_BRAKE"}, problems
