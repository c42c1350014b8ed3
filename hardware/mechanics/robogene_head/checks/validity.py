# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Every part is one valid, closed solid with a positive volume (a board: one per PCB body and component model)."""
from __future__ import annotations

from dataclasses import dataclass

from OCP.BRepCheck import BRepCheck_Analyzer

from ..parts import Part


@dataclass
class SolidCheck:
    name: str
    valid: bool
    solids: int
    closed: bool
    volume: float
    expected_solids: int = 1

    @property
    def ok(self) -> bool:
        return self.valid and self.solids == self.expected_solids and self.closed and self.volume > 0


def check_part(part: Part) -> SolidCheck:
    shape = part.local
    solids = shape.Solids()
    closed = all(all(shell.Closed() for shell in s.Shells()) for s in solids)
    valid = BRepCheck_Analyzer(shape.wrapped).IsValid() and shape.isValid()
    return SolidCheck(part.name, valid, len(solids), closed, shape.Volume(), part.expected_solids)


def check_all(parts: list[Part]) -> list[SolidCheck]:
    return [check_part(p) for p in parts]
