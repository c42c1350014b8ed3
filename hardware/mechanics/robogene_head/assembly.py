# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The head assembly: every part placed in the world (neck base) frame for given joint angles, using the same
kinematic tree as the URDF (kinematics.link_poses)."""
from __future__ import annotations

from dataclasses import dataclass

import cadquery as cq
import numpy as np
from OCP.gp import gp_Trsf

from . import kinematics
from .params import HeadParameters
from .parts import Part, build_all


def location(matrix: np.ndarray) -> cq.Location:
    trsf = gp_Trsf()
    m = matrix
    trsf.SetValues(m[0, 0], m[0, 1], m[0, 2], m[0, 3],
                   m[1, 0], m[1, 1], m[1, 2], m[1, 3],
                   m[2, 0], m[2, 1], m[2, 2], m[2, 3])
    return cq.Location(trsf)


@dataclass
class Placed:
    part: Part
    world: np.ndarray   # link pose (4x4, mm)
    shape: cq.Shape     # geometry in the world frame


class Assembly:
    def __init__(self, params: HeadParameters, parts: list[Part] | None = None):
        self.params = params
        self.parts = parts if parts is not None else build_all(params)
        known = set(kinematics.links(params))
        for p in self.parts:
            if p.link not in known:
                raise ValueError(f"part {p.name}: link {p.link!r} is not in the kinematic tree")

    def pose(self, control: dict[str, float] | None = None, chain: dict[str, float] | None = None) -> list[Placed]:
        """Place every part. Give control-board angles (neck_pitch ... eyes_vergence) or chain angles."""
        angles = chain if chain is not None else kinematics.chain_angles(self.params, control)
        links = kinematics.link_poses(self.params, angles)
        return [Placed(p, links[p.link], p.shape.moved(location(links[p.link]))) for p in self.parts]

    def to_cq(self, control: dict[str, float] | None = None, name: str = "robogene_head") -> cq.Assembly:
        assy = cq.Assembly(name=name)
        for placed in self.pose(control):
            assy.add(placed.shape, name=placed.part.name, color=cq.Color(*placed.part.color))
        return assy
