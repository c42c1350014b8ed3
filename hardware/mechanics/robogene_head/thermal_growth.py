# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""How far a shaft grows against its housing between its fixed and a floating bearing, from the two parts' own
materials (bearing_arrangement.expansion, per key of `materials:`).

Three cases, from the temperature the head was assembled at: the shaft temperature_difference warmer than its
housing (the motor warms the stage it drives); both warmed together by temperature_rise; both warmed by
temperature_rise and the shaft temperature_difference more. The first governs a shaft of its housing's material (the
second is then nothing); a steel shaft in an aluminium housing shrinks against it as both warm, and the second can
govern. The floating ring needs room each way for the largest of them, whichever way it goes."""
from __future__ import annotations

from dataclasses import dataclass

from robogene_head_model.params import HeadParameters, ParameterError


@dataclass(frozen=True)
class Growth:
    shaft: str            # material keys
    housing: str
    cases: tuple          # (description, mm: the shaft's growth less the housing's, + away from the fixed bearing)
    governs: str          # the case with the largest magnitude
    mm: float             # its magnitude


def expansion(params: HeadParameters, material: str, part: str) -> float:
    """1/K of a part's material."""
    table = params.root.node("bearing_arrangement").node("expansion")
    if not table.has(material):
        raise ParameterError(f"{params.path}: bearing_arrangement.expansion: no coefficient for {material!r}, the "
                             f"material of {part}")
    return table.num(material, positive=True)


def differential(params: HeadParameters, shaft: tuple[str, str], housing: tuple[str, str], span: float) -> Growth:
    """The shaft's growth less its housing's over `span` mm; shaft and housing as (part name, material)."""
    node = params.root.node("bearing_arrangement")
    dt = node.num("temperature_difference", positive=True)
    rise = node.num("temperature_rise", positive=True)
    a_s, a_h = expansion(params, shaft[1], shaft[0]), expansion(params, housing[1], housing[0])
    cases = ((f"shaft {dt:g} K warmer", a_s * dt * span),
             (f"both warmed {rise:g} K", (a_s - a_h) * rise * span),
             (f"both warmed {rise:g} K, the shaft {dt:g} K more", (a_s * (rise + dt) - a_h * rise) * span))
    governs, mm = max(cases, key=lambda c: abs(c[1]))
    return Growth(shaft[1], housing[1], cases, governs, abs(mm))
