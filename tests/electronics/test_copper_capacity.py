# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The routed board's copper carries each power path's current at a 20 degC rise (IPC-2221, the declared
stackup), computed from the tracks and vias in the committed .kicad_pcb (hardware/electronics/checks/
copper_capacity.py). Rev B failed it: 0.4-0.45 mm motor tracks (about 1.8 A) and a single 0.4 mm via between
the FET and each driver's supply (about 1.3 A) for a 3.6 A driver."""
import pathlib

import pytest
import yaml

import copper_capacity as cc
from conftest import PCB, ROOT

CATALOG = yaml.safe_load((ROOT / "hardware" / "bom" / "catalog.yaml").read_text())["parts"]
PARAMS = yaml.safe_load((ROOT / "hardware" / "head-parameters.yaml").read_text())
DRIVER_A = CATALOG["ti-DRV8872DDAR"]["current_rating"]
FUSE_A = CATALOG["littelfuse-0451005.MRL"]["current_rating"]
# What one board draws at 12 V besides its motors: MCU, CAN transceiver, two quadrature and two absolute
# encoders, buffers and LED through the buck (about 2.5 W with margin).
LOGIC_A = 0.25


def chain_amps():
    """The daisy chain's current where it enters the first board: every motor at its configured current
    limit (the firmware enforces them) plus every board's logic."""
    joints = PARAMS["motor_control"]["joints"]
    return sum(j["current_limit"] for j in joints.values()) / 1000 + PARAMS["boards"]["count"] * LOGIC_A


def brake_amps(axis):
    """The largest holding-brake coil current (coil power / voltage) on board axis `axis` of any board."""
    amps = []
    for board in PARAMS["motor_control"]["boards"]:
        joint = board["axes"][axis]
        brake = PARAMS["drives"].get(joint, {}).get("brake")
        if brake:
            spec = PARAMS["purchased"][brake]
            amps.append(spec["power_W"] / spec["voltage"])
    return max(amps, default=0.0)


# (net, from part, to part, amperes): each H-bridge's supply, motor leads and return; the fused input; each
# brake coil's supply and return (rev D: header -> switch, and +12V to the header).
PATHS = [
    ("/M1_OUT1", "U5", "R30", DRIVER_A), ("/M1_MA", "R30", "J20", DRIVER_A), ("/M1_OUT2", "U5", "J20", DRIVER_A),
    ("/M2_OUT1", "U7", "R40", DRIVER_A), ("/M2_MA", "R40", "J30", DRIVER_A), ("/M2_OUT2", "U7", "J30", DRIVER_A),
    ("+12V", "Q1", "U5", DRIVER_A), ("+12V", "Q1", "U7", DRIVER_A),
    ("GND", "U5", "J1", DRIVER_A), ("GND", "U7", "J1", DRIVER_A),
    ("/VIN_RAW", "J1", "F1", FUSE_A), ("/VIN_FUSED", "F1", "Q1", FUSE_A),
    ("/VIN_RAW", "J1", "J5", chain_amps()), ("GND", "J1", "J5", chain_amps()),
    ("+12V", "Q1", "J23", brake_amps(0)), ("/M1_BRAKE_N", "J23", "Q30", brake_amps(0)), ("GND", "Q30", "J1", brake_amps(0)),
    ("+12V", "Q1", "J33", brake_amps(1)), ("/M2_BRAKE_N", "J33", "Q40", brake_amps(1)), ("GND", "Q40", "J1", brake_amps(1)),
]


@pytest.fixture(scope="module")
def board():
    return cc.read_board(PCB)


def _shortfalls(board):
    out = []
    for net, a, b, amps in PATHS:
        try:
            have = cc.Network(board, net).capacity(a, b)
        except cc.BoardReadError as exc:
            out.append(f"{net} {a} -> {b}: {exc}")
            continue
        if have < amps:
            narrow = cc.narrowest_track(board, net)
            out.append(f"{net} {a} -> {b}: {have:.2f} A < {amps:.2f} A (narrowest track: "
                       f"{'none' if narrow is None else f'{narrow[0]:.3f} mm on {narrow[1]}'})")
    return out


def test_every_power_path_carries_its_current(board):
    shortfalls = _shortfalls(board)
    assert shortfalls == [], "\n".join(shortfalls)


def test_the_chain_current_is_computed_from_the_head():
    assert 7 < chain_amps() < 10   # 7.02 A of current limits + 3 x 0.25 A


def test_ipc2221_figures():
    # published IPC-2221 examples: 1 oz outer copper, 10 degC rise, 1 A needs ~0.3 mm (12 mil)
    assert cc.ipc2221_amps(0.3, 0.035, outer=True, rise_c=10) == pytest.approx(1.0, rel=0.1)
    # inner layers carry about half
    assert cc.ipc2221_amps(1.0, 0.035, outer=False) == pytest.approx(cc.ipc2221_amps(1.0, 0.035, outer=True) / 2)
    # rev B's 0.45 mm motor track: about 1.8 A at 20 degC rise
    assert cc.ipc2221_amps(0.45, 0.035, outer=True) == pytest.approx(1.8, abs=0.15)


def _board_text(tmp_path, edit):
    text = PCB.read_text()
    out = tmp_path / PCB.name
    out.write_text(edit(text))
    return cc.read_board(out)


def test_the_check_fails_on_a_narrowed_motor_track(tmp_path):
    """A broken variant: every motor-lead track of M1_OUT2 at rev B's 0.45 mm."""
    import re

    def narrow(text):
        net = re.search(r'\(net (\d+) "/M1_OUT2"\)', text).group(1)
        return re.sub(r'(\(segment\n(?:\t\t[^\n]*\n)*?\t\t\(width )[\d.]+(\)\n(?:\t\t[^\n]*\n)*?\t\t\(net ' + net + r'\)\n)',
                      r"\g<1>0.45\g<2>", text)

    broken = _board_text(tmp_path, narrow)
    assert cc.narrowest_track(broken, "/M1_OUT2")[0] == 0.45
    assert any(s.startswith("/M1_OUT2 U5 -> J20") for s in _shortfalls(broken))


def test_a_missing_stackup_falls_back_to_1oz_and_fails(tmp_path):
    """Without the declared 2 oz outer copper, the 0.7 mm motor tracks are short of 3.6 A."""
    import re
    broken = _board_text(tmp_path, lambda t: re.sub(r"\n\t\t\(stackup\n.*?\n\t\t\)\n", "\n", t, count=1, flags=re.S))
    assert not broken.declared_stackup
    assert set(broken.copper.values()) == {cc.OZ1_MM}
    assert any(s.startswith("/M1_OUT1 U5 -> R30") for s in _shortfalls(broken))


def test_a_board_that_is_not_kicad_is_named(tmp_path):
    bad = tmp_path / "x.kicad_pcb"
    bad.write_text("(not_a_board)")
    with pytest.raises(cc.BoardReadError, match="x.kicad_pcb"):
        cc.read_board(bad)


def test_the_board_declares_its_4_layer_stackup(board):
    """The fabricator builds what the file declares, and the capacity check reads the copper from it."""
    assert board.declared_stackup
    assert list(board.copper) == ["F.Cu", "In1.Cu", "In2.Cu", "B.Cu"]
    # 2 oz finished copper outside (the current paths), 1 oz inside
    assert [board.copper[l] for l in board.copper] == pytest.approx([0.07, 0.035, 0.035, 0.07])
