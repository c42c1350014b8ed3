# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The motor-control board as KiCad exports it (build/fab/electronics/board.step, mk/electronics.mk).

kicad-cli writes the board with its origin at the outline centre, the PCB body from z = 0 up and the
component models on +z (through-hole pins reach below). The PCB body is the solid that spans the whole
outline; every other solid is a component model. A missing, unreadable or differently placed STEP stops
the build with a message naming the file and what is wrong."""
from __future__ import annotations

import hashlib
from dataclasses import dataclass
from pathlib import Path

import cadquery as cq
from OCP.IFSelect import IFSelect_RetDone
from OCP.Interface import Interface_Static
from OCP.STEPControl import STEPControl_Reader

ORIGIN_TOLERANCE = 0.01   # mm


class BoardModelError(ValueError):
    """A board STEP problem; the message starts with the file."""


@dataclass(frozen=True)
class BoardModel:
    path: Path
    sha256: str               # of the STEP file's bytes: the build's caches key on it
    solids: tuple[cq.Solid, ...]
    pcb_index: int            # which solid is the PCB body

    @property
    def shape(self) -> cq.Compound:
        return cq.Compound.makeCompound(list(self.solids))

    @property
    def pcb(self) -> cq.Solid:
        return self.solids[self.pcb_index]

    @property
    def size(self) -> tuple[float, float, float]:
        bb = self.shape.BoundingBox()
        return bb.xlen, bb.ylen, bb.zlen

    @property
    def z_range(self) -> tuple[float, float]:
        """Lowest pin end and highest component top, relative to the PCB's bottom face."""
        bb = self.shape.BoundingBox()
        return bb.zmin, bb.zmax


_loaded: dict[tuple[str, str], BoardModel] = {}


def load(path: Path | str) -> BoardModel:
    path = Path(path)
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        raise BoardModelError(f"{path}: board STEP not found (build it with `make electronics`, or give another "
                              f"file with --board-step)") from None
    except OSError as exc:
        raise BoardModelError(f"{path}: cannot read the board STEP: {exc.strerror}") from None
    sha = hashlib.sha256(data).hexdigest()
    key = (str(path.resolve()), sha)
    if key not in _loaded:
        _loaded[key] = _read(path, sha)
    return _loaded[key]


def _read(path: Path, sha: str) -> BoardModel:
    Interface_Static.SetCVal_s("xstep.cascade.unit", "MM")
    reader = STEPControl_Reader()
    if reader.ReadFile(str(path)) != IFSelect_RetDone:
        raise BoardModelError(f"{path}: not a readable STEP file")
    if reader.TransferRoots() == 0:
        raise BoardModelError(f"{path}: the STEP file holds no shape")
    solids = tuple(cq.Shape.cast(reader.OneShape()).Solids())
    if not solids:
        raise BoardModelError(f"{path}: the STEP file holds no solid (expected the PCB body and its components)")
    whole = cq.Compound.makeCompound(list(solids)).BoundingBox()
    spanning = [i for i, s in enumerate(solids) if _spans(s.BoundingBox(), whole)]
    if len(spanning) != 1:
        raise BoardModelError(f"{path}: expected one solid spanning the board outline "
                              f"({whole.xlen:.2f} x {whole.ylen:.2f} mm), the PCB body; found {len(spanning)}")
    pcb = solids[spanning[0]].BoundingBox()
    off = (abs(pcb.xmin + pcb.xmax) / 2, abs(pcb.ymin + pcb.ymax) / 2, abs(pcb.zmin))
    if max(off) > ORIGIN_TOLERANCE:
        raise BoardModelError(f"{path}: the PCB body's centre is at ({(pcb.xmin + pcb.xmax) / 2:.3f}, "
                              f"{(pcb.ymin + pcb.ymax) / 2:.3f}) and its bottom face at z = {pcb.zmin:.3f}; expected "
                              f"the origin at the outline centre on the bottom face (kicad-cli --user-origin)")
    return BoardModel(path, sha, solids, spanning[0])


def _spans(box, whole) -> bool:
    return (abs(box.xmin - whole.xmin) < ORIGIN_TOLERANCE and abs(box.xmax - whole.xmax) < ORIGIN_TOLERANCE and
            abs(box.ymin - whole.ymin) < ORIGIN_TOLERANCE and abs(box.ymax - whole.ymax) < ORIGIN_TOLERANCE)
