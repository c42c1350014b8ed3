# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The head assembly: every part placed in the world (neck base) frame for given joint angles, using the same
kinematic tree as the URDF (kinematics.link_poses)."""
from __future__ import annotations

from dataclasses import dataclass

import cadquery as cq
import numpy as np

from robogene_head_model.params import HeadParameters

from . import kinematics
from .geom import location
from .external import ExternalGeometry
from .parts import Part, build_all


@dataclass
class Placed:
    part: Part
    world: np.ndarray   # link pose (4x4, mm)
    shape: cq.Shape     # geometry in the world frame


class Assembly:
    def __init__(self, params: HeadParameters, parts: list[Part] | None = None,
                 external: ExternalGeometry | None = None):
        """The whole head from the parameters and the external geometry, or a given list of parts."""
        self.params = params
        if parts is None:
            if external is None:
                raise ValueError("the head assembly needs the board STEP and the face plate (robogene_head.external)")
            parts = build_all(params, external)
        self.parts = parts
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
            pieces = placed.part.pieces(placed.shape)
            if len(pieces) == 1:
                assy.add(placed.shape, name=placed.part.name, color=cq.Color(*placed.part.color, placed.part.alpha))
                continue
            sub = cq.Assembly(name=placed.part.name)
            for label, shape, color in pieces:
                sub.add(shape, name=label, color=cq.Color(*color, placed.part.alpha))
            assy.add(sub)
        return assy
