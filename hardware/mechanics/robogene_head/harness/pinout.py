# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The motor-control board's connectors as the harness needs them: each pin's net from the board's design table
(hardware/electronics/generator/design.py, which the schematic and the PCB are generated from), and each
connector's place on the board from the KiCad PCB, in the board STEP's frame (origin at the outline centre, y up)."""
from __future__ import annotations

import importlib.util
import math
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

REPO = Path(__file__).resolve().parents[4]
GENERATOR = REPO / "hardware" / "electronics" / "generator"
PCB = REPO / "hardware" / "electronics" / "motor-board" / "robogene-motor-board.kicad_pcb"


class PinoutError(ValueError):
    pass


@dataclass(frozen=True)
class Connector:
    ref: str
    mpn: str                       # the header's order code (B4B-PH-K-S(LF)(SN) ...)
    description: str
    nets: tuple[str, ...]          # by pin, 1..n; "" for a pin left open
    at: tuple[float, float]        # pin 1, board frame (mm)
    centre: tuple[float, float]    # the pins' centre, board frame (mm)
    # The header's body as the footprint draws it on F.Fab (KiCad draws it from the maker's drawing): x0, x1, y0, y1
    # of its outline in the board frame. The board-bay check stands the mated plug on it.
    body: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)

    @property
    def pins(self) -> int:
        return len(self.nets)


def _load(name: str):
    spec = importlib.util.spec_from_file_location(f"robogene_board_{name}", GENERATOR / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@lru_cache(maxsize=None)
def connectors(pcb: Path = PCB) -> dict[str, Connector]:
    """Every J* part of the board, by reference."""
    design, sexpr = _load("design"), _load("sexpr")
    parts = {p.ref: p for p in design.parts() if p.ref.startswith("J")}
    try:
        tree = sexpr.parse(pcb.read_text(encoding="utf-8"), str(pcb))
    except OSError as exc:
        raise PinoutError(f"{pcb}: cannot read the board: {exc.strerror}") from None
    outline = [e for e in tree if isinstance(e, list) and e and e[0] == "gr_line" and _layer(e) == "Edge.Cuts"]
    xs = [float(v) for e in outline for key in ("start", "end") for v in _get(e, key)[1:2]]
    ys = [float(v) for e in outline for key in ("start", "end") for v in _get(e, key)[2:3]]
    if not xs:
        raise PinoutError(f"{pcb}: no board outline on Edge.Cuts")
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    out = {}
    for fp in (e for e in tree if isinstance(e, list) and e and e[0] == "footprint"):
        ref = next((p[2] for p in fp if isinstance(p, list) and p[:2] == ["property", "Reference"]), None)
        if ref not in parts:
            continue
        at = _get(fp, "at")
        fx, fy, rot = float(at[1]), float(at[2]), math.radians(float(at[3]) if len(at) > 3 else 0.0)
        def to_board(px: float, py: float) -> tuple[float, float]:
            # KiCad turns a footprint counter-clockwise on screen, whose y points down; the STEP's y points up.
            kx = fx + px * math.cos(rot) + py * math.sin(rot)
            ky = fy - px * math.sin(rot) + py * math.cos(rot)
            return round(kx - cx, 4), round(cy - ky, 4)

        pads = {}
        for pad in (e for e in fp if isinstance(e, list) and e and e[0] == "pad"):
            pads[str(pad[1])] = to_board(*(float(v) for v in _get(pad, "at")[1:3]))
        fab = [to_board(float(e[1]), float(e[2])) for g in fp if isinstance(g, list) and g and
               g[0] in ("fp_line", "fp_rect") and _layer(g) == "F.Fab"
               for e in g if isinstance(e, list) and e and e[0] in ("start", "end")]
        if not fab:
            raise PinoutError(f"{pcb}: {ref} has no body outline on F.Fab")
        body = (min(x for x, _ in fab), max(x for x, _ in fab), min(y for _, y in fab), max(y for _, y in fab))
        part = parts[ref]
        n = len(part.pins)
        missing = [str(i) for i in range(1, n + 1) if str(i) not in pads]
        if missing:
            raise PinoutError(f"{pcb}: {ref} has no pad {', '.join(missing)}")
        cxp = sum(p[0] for p in pads.values()) / len(pads)
        cyp = sum(p[1] for p in pads.values()) / len(pads)
        nets = tuple(part.pins[str(i)] or "" for i in range(1, n + 1))
        out[ref] = Connector(ref, part.mpn, part.description, nets, pads["1"], (round(cxp, 4), round(cyp, 4)),
                             body)
    missing = sorted(set(parts) - set(out))
    if missing:
        raise PinoutError(f"{pcb}: connectors {', '.join(missing)} of the design are not on the board")
    return out


def _get(expr, key):
    for e in expr:
        if isinstance(e, list) and e and e[0] == key:
            return e
    raise PinoutError(f"{PCB}: a {expr[0]} has no ({key} ...)")


def _layer(expr) -> str:
    for e in expr:
        if isinstance(e, list) and e and e[0] == "layer":
            return str(e[1])
    return ""
