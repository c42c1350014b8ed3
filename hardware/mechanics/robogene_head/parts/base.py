# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The Part record shared by every part family."""
from __future__ import annotations

from dataclasses import dataclass, field

import cadquery as cq

# machined / printed parts are made from our drawings; purchased parts are envelopes of catalog items;
# boards are the motor-control boards as KiCad exports them (their parts come from the board BOM).
KINDS = ("machined", "printed", "purchased", "board")


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
    alpha: float = 1.0   # opacity in renders and the GLB (the face plate is see-through there)
    # Parts of several solids (a board: PCB body + component models) give a material per solid of `local`,
    # in the order of local.Solids(); all other parts are one solid of `material`.
    solid_materials: tuple[str, ...] = ()
    source_sha256: str = ""   # geometry read from another tool's file: that file's hash, for the build's caches
    turning: bool = False     # a shaft that turns in bearings of its own link (the fits: its ring is the tight one)
    clamp_bores: tuple[float, ...] = ()   # machined: bores that clamp a shaft (their fit: fits.clamp_bore)

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"part {self.name}: unknown kind {self.kind!r}")

    @property
    def expected_solids(self) -> int:
        return len(self.solid_materials) or 1

    def pieces(self, shape: cq.Shape) -> list[tuple[str, cq.Shape, tuple[float, float, float]]]:
        """(label, geometry, colour) for display: one piece, or one per material of a multi-solid part.
        `shape` is this part's geometry in any frame (local, link or world)."""
        if not self.solid_materials:
            return [(self.name, shape, self.color)]
        groups: dict[str, list[cq.Solid]] = {}
        for solid, material in zip(shape.Solids(), self.solid_materials):
            groups.setdefault(material, []).append(solid)
        return [(f"{self.name}_{material}", cq.Compound.makeCompound(solids), MATERIAL_COLORS.get(material, self.color))
                for material, solids in groups.items()]

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

# Materials of a board's solids (keys of materials in the parameter file) and their display colours.
PCB_MATERIAL = "pcb-fr4-4-layer"
COMPONENTS_MATERIAL = "board-components"
MATERIAL_COLORS = {PCB_MATERIAL: GREEN, COMPONENTS_MATERIAL: DARK}
