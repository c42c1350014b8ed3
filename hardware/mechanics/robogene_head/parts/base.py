# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The Part record shared by every part family."""
from __future__ import annotations

from dataclasses import dataclass, field

import cadquery as cq

# machined / printed parts are made from our drawings; purchased parts are envelopes of catalog items;
# reserved volumes (the motor-control boards) keep space free for issue 5's electronics.
KINDS = ("machined", "printed", "purchased", "reserved")


@dataclass
class Part:
    name: str            # unique instance name
    design: str          # one STEP/STL/drawing per design; purchased parts: the catalog key
    link: str            # kinematic link the part is fixed to
    kind: str
    local: cq.Shape      # geometry in the design's own frame
    placement: cq.Location = field(default_factory=cq.Location)  # design frame -> link frame
    material: str = ""   # machined / printed: key of materials in the parameter file
    mass: float | None = None  # purchased: datasheet mass (kg), spread over the envelope
    color: tuple[float, float, float] = (0.7, 0.7, 0.7)
    note: str = ""

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"part {self.name}: unknown kind {self.kind!r}")

    @property
    def shape(self) -> cq.Shape:
        """Geometry in the link frame."""
        return self.local.moved(self.placement)


def loc(x=0.0, y=0.0, z=0.0, rz=0.0, rx=0.0, ry=0.0) -> cq.Location:
    """Translation after rotations about x, then y, then z (degrees)."""
    location = cq.Location(cq.Vector(x, y, z))
    if rz:
        location = location * cq.Location(cq.Vector(), cq.Vector(0, 0, 1), rz)
    if ry:
        location = location * cq.Location(cq.Vector(), cq.Vector(0, 1, 0), ry)
    if rx:
        location = location * cq.Location(cq.Vector(), cq.Vector(1, 0, 0), rx)
    return location


ALUMINIUM = (0.72, 0.74, 0.78)
PRINTED = (0.95, 0.55, 0.12)
DARK = (0.15, 0.15, 0.17)
STEEL = (0.55, 0.57, 0.6)
GREEN = (0.1, 0.45, 0.2)
