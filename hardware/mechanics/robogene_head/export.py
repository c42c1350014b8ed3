# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Writers for the fabrication package: STEP, STL, link meshes, assembly STEP/GLB, and geometry hashes."""
from __future__ import annotations

import hashlib
import io
import re
from pathlib import Path

import cadquery as cq
from OCP.BRepTools import BRepTools
from OCP.BRepMesh import BRepMesh_IncrementalMesh
from OCP.StlAPI import StlAPI_Writer
from OCP.TopTools import TopTools_FormatVersion

from .parts import Part

LINEAR_TOLERANCE = 0.05   # mm chordal deviation of STL meshes
ANGULAR_TOLERANCE = 0.2   # rad
# In the BRep text, each shape's state flags (free, modified, checked, ...) are a line of seven 0/1 digits just
# before the list of its sub-shapes (orientation +, -, i or e, then indices; '*' ends the list).
_FLAGS = re.compile(rb"^[01]{7}\n(?=[-+ie*])", re.M)


def shape_hash(shape: cq.Shape, *extra: str) -> str:
    """A content hash of the exact B-rep (plus any extra labels): equal geometry -> equal hash. Meshing a shape (an
    STL, a link mesh) attaches triangulations and sets its sub-shapes' "checked" flags; both are left out, or a build
    that exported a part and one that found it cached would hash it differently and redraw what depends on it."""
    stream = io.BytesIO()
    BRepTools.Write_s(shape.wrapped, stream, False, False, TopTools_FormatVersion.TopTools_FormatVersion_VERSION_1)
    h = hashlib.sha256(_FLAGS.sub(b"", stream.getvalue()))
    for label in extra:
        h.update(b"\0" + label.encode())
    return h.hexdigest()


def write_step(shape: cq.Shape, path: Path, name: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    assy = cq.Assembly(shape, name=name)
    assy.export(str(path), "STEP")


def write_stl(shape: cq.Shape, path: Path) -> None:
    """Binary STL of a closed shape, meshed with the package's tolerances."""
    path.parent.mkdir(parents=True, exist_ok=True)
    mesh = BRepMesh_IncrementalMesh(shape.wrapped, LINEAR_TOLERANCE, False, ANGULAR_TOLERANCE, True)
    mesh.Perform()
    writer = StlAPI_Writer()
    writer.ASCIIMode = False
    if not writer.Write(shape.wrapped, str(path)):
        raise RuntimeError(f"STL export failed: {path}")


def link_solid(parts: list[Part]) -> cq.Shape:
    """The parts of one link fused into as few solids as possible, so the mesh has no internal faces and
    touching parts do not share edges between separate shells."""
    shapes = [p.shape for p in parts]
    # No clean(): on the neck base, merging coplanar faces after this fuse gave an invalid shape.
    return shapes[0].fuse(*shapes[1:]) if len(shapes) > 1 else shapes[0]
