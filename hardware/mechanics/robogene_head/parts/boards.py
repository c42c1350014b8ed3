# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Space reserved for the motor-control boards (issue 5) in the neck base's board bay."""
from __future__ import annotations

from .. import geom
from ..params import HeadParameters
from .base import GREEN, Part, loc


def build(params: HeadParameters) -> list[Part]:
    b = params.root.node("boards")
    env = b.node("envelope")
    l, w, h = env.num("length", positive=True), env.num("width", positive=True), env.num("height", positive=True)
    names = b.raw("names")
    if not isinstance(names, list) or len(names) != int(b.num("count", positive=True)):
        raise b._fail("names", f"expected a list of {int(b.num('count'))} board names")
    ox, oy, oz = b.vec("origin")
    pitch = b.num("stack_pitch", positive=True)
    if pitch < h:
        raise b._fail("stack_pitch", f"{pitch} is below the envelope height {h}: the boards would overlap")
    shape = geom.box(-l / 2, l / 2, -w / 2, w / 2, -h / 2, h / 2)
    return [Part(f"board_{name}", "board_envelope", "neck_base", "reserved", shape, loc(ox, oy, oz + i * pitch),
                 color=GREEN, note="envelope reserved for the motor-control board " + name)
            for i, name in enumerate(names)]
