# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The harness's plugs mated on the motor-control boards' headers, as envelopes the board-bay check
(checks/board_bay.py) and the interference sweep see: KiCad's board STEP has the headers (not the VH ones) but no
mated housing and no wire.

Every header that a cable of `harness.cables` plugs into gets, on each board, a housing and a wire turn over the
header's body (its F.Fab outline in the KiCad board): the housing from the top of the header's model (the PCB's top
face where the STEP has none) up to the mated height above the PCB's top face (`boards.plugs.mated_height`, by the
header's order code); above it the wires, which leave the housing's top and turn sideways, bent no tighter than
`boards.plugs.wire_bend_factor` times their od: the turn reaches that radius plus half an od above the housing.
A header the STEP has no model of (JST VH) also gets its solder tails under the PCB, as deep as the board's deepest
through-hole pin, so the plug of the board below sees them."""
from __future__ import annotations

from dataclasses import dataclass

import cadquery as cq
import numpy as np
from OCP.Bnd import Bnd_Box
from OCP.BRepBndLib import BRepBndLib

from robogene_head_model.params import HeadParameters, ParameterError

from .. import geom
from ..board_model import BoardModel
from ..harness import pinout, spec
from .base import Part, loc

# A component model belongs to a header when its box lies within the header's outline, to this margin (mm): the
# F.Fab outline and the model are drawn from the same drawing, a few hundredths apart.
OUTLINE_MARGIN = 0.5


@dataclass(frozen=True)
class Plug:
    board: str             # boards.names entry
    ref: str               # the header's reference (J20 ...)
    mpn: str               # the header's order code
    cable: str             # the harness cable that ends in it
    base: float            # where the housing stands, above the PCB's bottom face (mm)
    housing_top: float     # the mated housing's top, above the PCB's bottom face
    wire_top: float        # the wires' turn's top, above the PCB's bottom face
    wire_od: float
    part: Part             # housing and wire turn, one solid, placed in the neck base's frame

    @property
    def housing(self) -> str:
        return self.part.design


def _cable_ends(params: HeadParameters) -> dict[tuple[str, str], spec.Cable]:
    """(board, ref) -> the cable plugged in there, from either end of the harness's cables."""
    ends: dict[tuple[str, str], spec.Cable] = {}
    for cable in spec.load(params).cables:
        ends.setdefault((cable.board, cable.ref), cable)
        if isinstance(cable.to, tuple):
            ends.setdefault(tuple(cable.to), cable)
    return ends


def loose_box(shape: cq.Shape) -> tuple[np.ndarray, np.ndarray]:
    """A box around the shape, possibly a little larger than the exact one, and fast (no optimal bounds). From the
    geometry, never a triangulation: a shape meshed earlier in the run (the GLB export) would give another box, and
    the plugs, which the interference check's cache keys on, another shape."""
    found = Bnd_Box()
    BRepBndLib.Add_s(shape.wrapped, found, False)
    x0, y0, z0, x1, y1, z1 = found.Get()
    return np.array([x0, y0, z0]), np.array([x1, y1, z1])


def _header_top(boxes, pcb_index: int, body: tuple[float, float, float, float]) -> float | None:
    """The top of the header's model above the PCB's bottom face; None when the STEP has no model there."""
    x0, x1, y0, y1 = body
    tops = [hi[2] for i, (lo, hi) in enumerate(boxes) if i != pcb_index and
            lo[0] > x0 - OUTLINE_MARGIN and hi[0] < x1 + OUTLINE_MARGIN and
            lo[1] > y0 - OUTLINE_MARGIN and hi[1] < y1 + OUTLINE_MARGIN]
    return max(tops) if tops else None


def build(params: HeadParameters, board: BoardModel, connectors: dict | None = None) -> list[Plug]:
    connectors = connectors if connectors is not None else pinout.connectors()
    b = params.root.node("boards")
    where = f"{params.path}: boards.plugs"
    plugs = b.node("plugs")
    factor = plugs.num("wire_bend_factor", positive=True)
    heights = plugs.node("mated_height")
    mating = params.root.node("harness").node("mating")
    names = list(b.raw("names"))
    ox, oy, oz = b.vec("origin")
    pitch, thickness = b.num("stack_pitch", positive=True), b.num("thickness", positive=True)
    boxes = [loose_box(s) for s in board.solids]
    deepest_pin = min(lo[2] for lo, _ in boxes)
    out: list[Plug] = []
    for (name, ref), cable in sorted(_cable_ends(params).items(), key=lambda kv: (names.index(kv[0][0]), kv[0][1])):
        c = connectors.get(ref)
        if c is None:
            raise ParameterError(f"{params.path}: harness.cables.{cable.name}: the board has no connector {ref}")
        if not heights.has(c.mpn):
            raise ParameterError(f"{where}.mated_height: no entry for {c.mpn} ({ref}, cable {cable.name})")
        mated = heights.num(c.mpn, positive=True)
        header = _header_top(boxes, board.pcb_index, c.body)
        base = thickness if header is None else header
        housing_top = thickness + mated
        if housing_top <= base:
            raise ParameterError(f"{where}.mated_height.{c.mpn}: {mated:g} mm above the PCB leaves the plug inside "
                                 f"{ref}'s header, whose model reaches {base - thickness:.2f} mm above it")
        od = cable.cls.od(c.pins)
        wire_top = housing_top + od * (factor + 0.5)
        x0, x1, y0, y1 = c.body
        shape = geom.box(x0, x1, y0, y1, base, wire_top)
        if header is None:
            tails = geom.box(x0, x1, y0, y1, deepest_pin, 0.0)
            shape = cq.Compound.makeCompound([shape, tails])
        level = names.index(name)
        housing = mating.node(c.mpn).text("housing") if mating.has(c.mpn) else c.mpn
        part = Part(f"plug_{name}_{ref}", housing, "neck_base", "purchased", shape,
                    loc(ox, oy, oz + level * pitch), color=(0.92, 0.92, 0.88),
                    note=f"{housing} mated on {ref} of board {name} with the wires' turn above it (cable {cable.name})")
        out.append(Plug(name, ref, c.mpn, cable.name, base, housing_top, wire_top, od, part))
    return out
