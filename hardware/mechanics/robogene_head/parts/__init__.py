# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Every part of the head, grouped by family; build_all() returns them placed in their link frames."""
from __future__ import annotations

from robogene_head_model.params import HeadParameters

from ..external import ExternalGeometry
from .base import Part
from . import board_stack, boards, covers, eyes, face, head_frame, joint_encoders, neck


def build_all(params: HeadParameters, external: ExternalGeometry) -> list[Part]:
    """external: the KiCad board and the OpenSCAD face plate (robogene_head.external)."""
    parts: list[Part] = []
    for family in (neck, head_frame, eyes, covers, joint_encoders):
        parts.extend(family.build(params))
    parts += face.build(params, external)
    parts += boards.build(params, external.board)
    parts += board_stack.build(params, external.board)
    names = [p.name for p in parts]
    dupes = sorted({n for n in names if names.count(n) > 1})
    if dupes:
        raise ValueError("duplicate part names: " + ", ".join(dupes))
    return parts


__all__ = ["Part", "build_all"]
