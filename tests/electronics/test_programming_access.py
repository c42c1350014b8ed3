# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Programming and recovery reach a board inside the stack: SWD, reset and BOOT0 on a right-angle header at
the board's edge, its mating side facing the edge with nothing in between (rev B had a vertical 1.27 mm
header in the middle of the board, buried under the next board, and no BOOT0 access). BOOT0 plus reset
start the STM32G4's ROM bootloader, which listens on FDCAN1 at PA11/PA12, where the transceiver is."""
import math

import pytest

import design
from conftest import PCB
from sexpr import find, find1, parse

HEADER = "J4"
EDGE_GAP_MM = 1.0   # the header's courtyard reaches this close to the board's edge


def _parts():
    return {p.ref: p for p in design.parts()}


def test_the_header_carries_swd_reset_and_boot0():
    parts = _parts()
    nets = set(parts[HEADER].pins.values())
    assert {"SWDIO", "SWCLK", "NRST", "BOOT0", "GND", "+3V3"} <= nets, nets
    mcu = parts["U1"]
    assert (mcu.pins["23"], mcu.pins["24"], mcu.pins["4"], mcu.pins["31"]) == ("SWDIO", "SWCLK", "NRST", "BOOT0")
    # BOOT0 is pulled down (normal boot) unless the header pulls it up
    assert any(p.lib_id == "Device:R" and set(p.pins.values()) == {"BOOT0", "GND"} for p in parts.values())


def test_the_rom_bootloader_can_reach_the_can_transceiver():
    mcu, can = _parts()["U1"], _parts()["U4"]
    assert (mcu.pins["21"], mcu.pins["22"]) == ("CAN_RX", "CAN_TX")      # PA11 = FDCAN1_RX, PA12 = FDCAN1_TX
    assert (can.pins["4"], can.pins["1"]) == ("CAN_RX", "CAN_TX")


def _outline(board):
    xs, ys = [], []
    for line in find(board, "gr_line"):
        if find1(line, "layer")[1] == "Edge.Cuts":
            for key in ("start", "end"):
                xs.append(find1(line, key)[1])
                ys.append(find1(line, key)[2])
    return min(xs), min(ys), max(xs), max(ys)


def _footprint(board, ref):
    for fp in find(board, "footprint"):
        if next(p[2] for p in find(fp, "property") if p[1] == "Reference") == ref:
            return fp
    raise AssertionError(f"{ref} not on the board")


def _courtyard(fp):
    at = find1(fp, "at")
    a = math.radians(at[3] if len(at) > 3 else 0)
    pts = []
    for kind in ("fp_line", "fp_rect"):
        for g in find(fp, kind):
            if find1(g, "layer")[1] != "F.CrtYd":
                continue
            for key in ("start", "end"):
                x, y = find1(g, key)[1:3]
                pts.append((at[1] + x * math.cos(a) + y * math.sin(a), at[2] - x * math.sin(a) + y * math.cos(a)))
    return min(p[0] for p in pts), min(p[1] for p in pts), max(p[0] for p in pts), max(p[1] for p in pts)


def test_the_header_is_right_angle_at_the_board_edge_with_a_clear_path():
    _check_edge_header(parse(PCB.read_text(), str(PCB)))


def test_the_edge_check_fails_on_a_header_moved_inwards():
    """A broken variant: the same header 10 mm further into the board."""
    text = PCB.read_text()
    start = text.index('(property "Reference" "J4"')
    fp_start = text.rindex("\n\t(footprint ", 0, start)
    at = text.index("\t\t(at ", fp_start)
    end = text.index(")", at)
    x, y, *rot = text[at + len("\t\t(at "):end].split()
    moved = text[:at] + f"\t\t(at {x} {float(y) + 10} {' '.join(rot)}".rstrip() + text[end:]
    with pytest.raises(AssertionError, match="from the nearest"):
        _check_edge_header(parse(moved, "moved"))


def _check_edge_header(board):
    fp = _footprint(board, HEADER)
    assert "Horizontal" in fp[1], f"{HEADER} is {fp[1]}: a vertical header is buried once the boards are stacked"
    x0, y0, x1, y1 = _outline(board)
    cx0, cy0, cx1, cy1 = _courtyard(fp)
    gaps = {"top": cy0 - y0, "bottom": y1 - cy1, "left": cx0 - x0, "right": x1 - cx1}
    side, gap = min(gaps.items(), key=lambda kv: kv[1])
    assert gap <= EDGE_GAP_MM, f"{HEADER}'s courtyard is {gap:.2f} mm from the nearest ({side}) edge"
    # the pins run towards that edge: the pads sit on the far side of the courtyard
    pads = [find1(p, "at") for p in find(fp, "pad")]
    at = find1(fp, "at")
    a = math.radians(at[3] if len(at) > 3 else 0)
    pad_y = [at[2] - p[1] * math.sin(a) + p[2] * math.cos(a) for p in pads]
    pad_x = [at[1] + p[1] * math.cos(a) + p[2] * math.sin(a) for p in pads]
    toward = {"top": min(pad_y) - cy0, "bottom": cy1 - max(pad_y), "left": min(pad_x) - cx0, "right": cx1 - max(pad_x)}
    assert toward[side] > 5.0, f"{HEADER}'s pins do not point at the {side} edge"
    # nothing else between the header and that edge
    for other in find(board, "footprint"):
        ref = next(p[2] for p in find(other, "property") if p[1] == "Reference")
        if ref == HEADER:
            continue
        ox0, oy0, ox1, oy1 = _courtyard(other) if any(find1(g, "layer")[1] == "F.CrtYd" for g in find(other, "fp_line") + find(other, "fp_rect")) else (0, 0, -1, -1)
        if side in ("top", "bottom"):
            between = ox0 < cx1 and ox1 > cx0 and (oy1 <= cy0 if side == "top" else oy0 >= cy1)
        else:
            between = oy0 < cy1 and oy1 > cy0 and (ox1 <= cx0 if side == "left" else ox0 >= cx1)
        assert not between, f"{ref} sits between {HEADER} and the {side} edge"
