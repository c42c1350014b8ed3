# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Every part of the head, grouped by family; build_all() returns them placed in their link frames."""
from __future__ import annotations

from ..params import HeadParameters
from .base import Part
from . import covers, eyes, head_frame, neck, boards


def build_all(params: HeadParameters) -> list[Part]:
    parts: list[Part] = []
    for family in (neck, head_frame, eyes, covers, boards):
        parts.extend(family.build(params))
    names = [p.name for p in parts]
    dupes = sorted({n for n in names if names.count(n) > 1})
    if dupes:
        raise ValueError("duplicate part names: " + ", ".join(dupes))
    return parts


__all__ = ["Part", "build_all"]
