# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The three motor-control boards in the neck base's board bay: the KiCad board STEP, placed once per board."""
from __future__ import annotations

from robogene_head_model.params import HeadParameters, ParameterError

from ..board_model import BoardModel
from .base import COMPONENTS_MATERIAL, GREEN, PCB_MATERIAL, Part, loc

DESIGN = "motor_board"


def build(params: HeadParameters, board: BoardModel) -> list[Part]:
    b = params.root.node("boards")
    names = b.raw("names")
    if not isinstance(names, list) or len(names) != int(b.num("count", positive=True)):
        raise b.fail("names", f"expected a list of {int(b.num('count'))} board names")
    ox, oy, oz = b.vec("origin")
    pitch = b.num("stack_pitch", positive=True)
    low, high = board.z_range
    gap = params.geometry("clearances").num("minimum")
    if pitch < high - low + gap:
        raise ParameterError(f"{params.path}: boards.stack_pitch: {pitch} leaves under {gap} mm between the boards: "
                             f"{board.path} reaches {low:.2f} below and {high:.2f} above its PCB's bottom face")
    materials = tuple(PCB_MATERIAL if i == board.pcb_index else COMPONENTS_MATERIAL for i in range(len(board.solids)))
    shape = board.shape
    return [Part(f"board_{name}", DESIGN, "neck_base", "board", shape, loc(ox, oy, oz + i * pitch), color=GREEN,
                 solid_materials=materials, source_sha256=board.sha256,
                 note=f"motor-control board {name}, from {board.path.name}")
            for i, name in enumerate(names)]
