# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The printed face plate (OpenSCAD, hardware/mechanics/scad/face_plate.scad) on the side plates' front edges,
with its four screws into the side plates' tapped holes."""
from __future__ import annotations

import numpy as np

from robogene_head_model.params import HeadParameters

from .. import geom
from ..external import ExternalGeometry
from . import purchased
from .base import Part, loc

SCREW = "iso7380-M3x8"
COLOR = (0.93, 0.93, 0.9)


def build(params: HeadParameters, external: ExternalGeometry) -> list[Part]:
    h = params.geometry("head")
    x_front = h.node("side_plate").num("x_max")
    y_screw = h.node("floor").num("half_width") - h.node("side_plate").num("thickness") / 2
    # OpenSCAD models the plate flat (x across the head, y up, z through the plate): its x is the head's y,
    # its y the head's z and its z the head's x, with its back face on the side plates' front edges.
    placement = geom.location(np.array([[0, 0, 1, x_front], [1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 1]], dtype=float))
    thickness = external.face_plate.BoundingBox().zmax
    parts = [Part("face_plate", "face_plate", "head_frame", "printed", external.face_plate, placement,
                  material="petg-printed", color=COLOR, alpha=0.55, source_sha256=external.face_plate_sha256)]
    for side, sign in (("left", 1), ("right", -1)):
        for k, z in enumerate(h.vec("face_screw_z", 2)):
            parts.append(purchased.screw(params, f"face_plate_screw_{side}_{k}", SCREW, "head_frame",
                                         loc(x_front + thickness, sign * y_screw, z, ry=-90)))
    return parts
