# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Mass, centre of mass and inertia of parts and links (kg, mm, kg*mm^2).

Made parts use their material's density; purchased envelopes spread their datasheet mass uniformly. A board
(the KiCad STEP) gives each of its solids a material: the PCB body one density, the component models another
(both in the parameter file's materials)."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from OCP.BRepGProp import BRepGProp
from OCP.GProp import GProp_GProps

from robogene_head_model.params import HeadParameters

from .parts import Part


@dataclass
class MassProps:
    mass: float              # kg
    com: np.ndarray          # mm
    inertia: np.ndarray      # kg*mm^2 about the centre of mass, axes of the frame used

    def moved(self, matrix: np.ndarray) -> "MassProps":
        rot = matrix[:3, :3]
        return MassProps(self.mass, rot @ self.com + matrix[:3, 3], rot @ self.inertia @ rot.T)


def combine(items: list[MassProps]) -> MassProps:
    items = [m for m in items if m.mass > 0]
    if not items:
        return MassProps(0.0, np.zeros(3), np.zeros((3, 3)))
    mass = sum(m.mass for m in items)
    com = sum(m.mass * m.com for m in items) / mass
    inertia = np.zeros((3, 3))
    for m in items:
        d = m.com - com
        inertia += m.inertia + m.mass * (np.dot(d, d) * np.eye(3) - np.outer(d, d))  # parallel axis
    return MassProps(mass, com, inertia)


def material_density(params: HeadParameters, material: str) -> float:
    """kg/mm^3."""
    return params.root.node("materials").num(material, positive=True) * 1e-9


def solid_props(shape, rho: float, name: str) -> MassProps:
    """Mass properties of a shape of uniform density rho (kg/mm^3), in the shape's own frame."""
    props = GProp_GProps()
    BRepGProp.VolumeProperties_s(shape.wrapped, props)
    volume = props.Mass()
    if volume <= 0:
        raise ValueError(f"part {name}: non-positive volume {volume}")
    c = props.CentreOfMass()
    m = props.MatrixOfInertia()  # about the centre of mass, volume-weighted
    inertia = np.array([[m.Value(i, j) for j in (1, 2, 3)] for i in (1, 2, 3)]) * rho
    return MassProps(volume * rho, np.array([c.X(), c.Y(), c.Z()]), inertia)


def part_props(params: HeadParameters, part: Part) -> MassProps:
    """Mass properties of a part in its link frame."""
    shape = part.shape
    if part.solid_materials:
        solids = shape.Solids()
        if len(solids) != len(part.solid_materials):
            raise ValueError(f"part {part.name}: {len(solids)} solids but {len(part.solid_materials)} materials")
        return combine([solid_props(s, material_density(params, m), part.name)
                        for s, m in zip(solids, part.solid_materials)])
    if part.kind == "purchased":
        volume = shape.Volume()
        if volume <= 0:
            raise ValueError(f"part {part.name}: non-positive volume {volume}")
        return solid_props(shape, part.mass / volume, part.name)
    return solid_props(shape, material_density(params, part.material), part.name)


def link_props(params: HeadParameters, parts: list[Part]) -> dict[str, MassProps]:
    by_link: dict[str, list[MassProps]] = {}
    for part in parts:
        by_link.setdefault(part.link, []).append(part_props(params, part))
    return {link: combine(items) for link, items in by_link.items()}
