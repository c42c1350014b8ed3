# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Geometry the head takes from other tools: the motor-control board from KiCad (board STEP) and the face
plate from OpenSCAD (STL rendered with the head's parameters). The assembly cannot be built without them."""
from __future__ import annotations

import hashlib
from dataclasses import dataclass
from pathlib import Path

import cadquery as cq

from robogene_head_model.params import HeadParameters

from . import board_model, mesh_solid, openscad

FACE_PLATE = "face_plate"   # the OpenSCAD printable that sits on the head; the others are loose (docs/fabricate.md)


@dataclass(frozen=True)
class ExternalGeometry:
    board: board_model.BoardModel
    face_plate: cq.Solid          # as OpenSCAD models it: lying flat, x across, y up, z through the plate
    face_plate_sha256: str        # of the STL's bytes


_solids: dict[str, cq.Solid] = {}


def load(board_step: Path, face_plate_stl: Path) -> ExternalGeometry:
    """Raises BoardModelError / MeshSolidError naming the file when one cannot be used."""
    board = board_model.load(board_step)
    try:
        sha = hashlib.sha256(Path(face_plate_stl).read_bytes()).hexdigest()
    except OSError as exc:
        raise mesh_solid.MeshSolidError(f"{face_plate_stl}: cannot read: {exc.strerror}") from None
    if sha not in _solids:
        _solids[sha] = mesh_solid.solid_from_stl(face_plate_stl)
    return ExternalGeometry(board, _solids[sha], sha)


def render_and_load(params: HeadParameters, board_step: Path, stl_dir: Path) -> ExternalGeometry:
    """Render the face plate for these parameters into stl_dir, then load both (tests and scripts; the
    fabrication build renders into its package and calls load)."""
    stl = Path(stl_dir) / f"{FACE_PLATE}.stl"
    openscad.render_stl(openscad.SCAD_DIR / f"{FACE_PLATE}.scad", openscad.defines(params)[FACE_PLATE], stl)
    return load(board_step, stl)
