# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The board bay with the harness plugged in: every mated plug and its wires' turn (parts/board_plugs.py) keeps
clearances.minimum from every other part of the neck base (the boards above, with their through-hole pins, the
standoffs, the base plate, the skirt) and from the other boards' plugs. On its own board a plug may only stand on
its header: any common volume with the board is a failure. The bay's parts are all on the neck base link, so one
pose is enough."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from robogene_head_model.params import HeadParameters

from .. import geom
from ..parts.board_plugs import Plug, loose_box

VOLUME_TOLERANCE = 0.5   # mm^3, as the interference check


@dataclass
class Row:
    plug: Plug
    nearest: str            # the closest other part within reach, "" when none
    distance: float | None  # to it (mm); None when nothing is within the minimum + 5 mm
    overlap: float = 0.0    # common volume with its own board (mm^3)


@dataclass
class Report:
    rows: list[Row]
    minimum: float

    @property
    def failures(self) -> list[Row]:
        return [r for r in self.rows if r.overlap > VOLUME_TOLERANCE or
                (r.distance is not None and r.distance < self.minimum)]

    @property
    def ok(self) -> bool:
        return not self.failures


def check(params: HeadParameters, parts, plugs: list[Plug]) -> Report:
    minimum = params.geometry("clearances").num("minimum", positive=True)
    reach = minimum + 5.0
    # solid by solid: a board is some sixty component models, and most are far from any one plug
    others = [(p.name, s) for p in parts if p.link == "neck_base" for s in p.shape.Solids()]
    others += [(q.part.name, s) for q in plugs for s in q.part.shape.Solids()]
    boxes = [loose_box(shape) for _, shape in others]
    rows = []
    for plug in plugs:
        shape = plug.part.shape
        lo, hi = loose_box(shape)
        own = f"board_{plug.board}"
        best: tuple[float, str] | None = None
        overlap = 0.0
        for (name, other), (olo, ohi) in zip(others, boxes):
            same_board_plug = name.startswith(f"plug_{plug.board}_")
            if name == plug.part.name:
                continue
            if np.any(np.maximum(lo, olo) - np.minimum(hi, ohi) > reach):
                continue
            if name == own or same_board_plug:
                # on its own board a plug stands on its header, beside its neighbours: only overlap counts
                if np.all(np.minimum(hi, ohi) - np.maximum(lo, olo) > 0):
                    overlap += shape.intersect(other).Volume()
                continue
            d = geom.distance(shape, other)
            if d <= reach and (best is None or d < best[0]):
                best = (d, name)
        rows.append(Row(plug, best[1] if best else "", best[0] if best else None, overlap))
    return Report(rows, minimum)


def format_report(report: Report) -> str:
    lines = [f"board bay: {len(report.rows)} mated plugs, each wanting {report.minimum:g} mm to every other part",
             "(heights above the PCB's bottom face; wire turn: the wires leaving the housing's top and turning sideways)",
             f"{'plug':<34} {'housing':<12} {'housing top':>11} {'wire od':>7} {'wire top':>8}  nearest part",
             ]
    for r in report.rows:
        p = r.plug
        near = f"{r.distance:6.2f} mm  {r.nearest}" if r.distance is not None else "none within reach"
        flag = ""
        if r.overlap > VOLUME_TOLERANCE:
            flag = f"  OVERLAPS its own board ({r.overlap:.1f} mm^3)"
        elif r.distance is not None and r.distance < report.minimum:
            flag = "  LOW"
        lines.append(f"{p.part.name:<34} {p.housing:<12} {p.housing_top:11.2f} {p.wire_od:7.2f} {p.wire_top:8.2f}  "
                     f"{near}{flag}")
    lines.append("board bay: " + ("ok" if report.ok else f"{len(report.failures)} plugs without room"))
    return "\n".join(lines)
