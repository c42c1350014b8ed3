# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""What holds the motor-control boards in the board bay: M3 male-female hex standoffs at the boards' four
mounting holes and a screw into each top standoff.

The stack stands on the neck base flange. The bottom standoffs' studs go into M3 holes tapped through the
flange; each board sits on the standoffs below it, and the studs of the standoffs above it pass through its
holes into those below, clamping it; M3 button-head screws clamp the top board. So the board pitch is a
standoff length plus the finished board thickness. KiCad's STEP draws the PCB body without its copper and
solder mask (1.51 of 1.6 mm), so in the model a standoff standing on a board is up to MASK_AND_COPPER above
the PCB body."""
from __future__ import annotations

import cadquery as cq

from robogene_head_model.params import HeadParameters, ParameterError

from .. import geom
from ..board_model import BoardModel
from . import purchased
from .base import Part, loc

# mm: the most the finished board may be thicker than the STEP's PCB body, which leaves out the outer copper and
# the mask: 0.16 on revision C's four-layer stack (2 oz outer copper, 0.07 a side; mask 0.01 a side).
MASK_AND_COPPER = 0.2
FLANGE_NOTE = "4 x M3 tapped through (tap drill 2.5), drawn at 3.0, for the board stack's standoffs"


def hole_positions(params: HeadParameters) -> list[tuple[float, float]]:
    """The boards' four mounting holes (x, y) about the board origin, which the stack shares with the base."""
    hx, hy = params.root.node("boards").vec("mounting_holes", 2)
    if hx <= 0 or hy <= 0:
        raise ParameterError(f"{params.path}: boards.mounting_holes: expected positive half-spacings, got {[hx, hy]}")
    ox, oy, _ = params.root.node("boards").vec("origin")
    return [(ox + sx * hx, oy + sy * hy) for sx in (-1, 1) for sy in (-1, 1)]


def flange_holes(params: HeadParameters, thickness: float) -> list[cq.Shape]:
    """Tapped holes for the bottom standoffs' studs, in the flange's frame (z 0..thickness), drawn at the thread."""
    thread = _standoff(params, "bottom").num("thread")
    return [geom.cyl("z", thread, -1, thickness + 1, c) for c in hole_positions(params)]


def _standoff(params: HeadParameters, role: str):
    key = params.root.node("boards").node("standoffs").text(role)
    node = params.purchased(key)
    if node.text("kind") != "standoff" or not node.has("stud_length"):
        raise ParameterError(f"{params.path}: boards.standoffs.{role}: {key} is not a male-female standoff "
                             f"(kind standoff with a stud_length)")
    return node


def build(params: HeadParameters, board: BoardModel) -> list[Part]:
    b = params.root.node("boards")
    count = int(b.num("count", positive=True))
    _, _, oz = b.vec("origin")
    pitch, thickness = b.num("stack_pitch", positive=True), b.num("thickness", positive=True)
    keys = b.node("standoffs")
    bottom, between = _standoff(params, "bottom"), _standoff(params, "between")
    screw_key = keys.text("screw")
    screw = params.purchased(screw_key)
    base = params.geometry("neck_base")
    flange_top = -base.node("plate").num("thickness") - base.num("bay_height")
    flange = base.node("flange").num("thickness")
    where = f"{params.path}: boards"

    pcb = board.pcb.BoundingBox().zlen
    if not thickness - MASK_AND_COPPER <= pcb <= thickness:
        raise ParameterError(f"{where}.thickness: {thickness} does not match {board.path.name}, whose PCB body is "
                             f"{pcb:.2f} mm thick (without copper and mask)")
    if abs(oz - (flange_top + bottom.num("length"))) > 1e-6:
        raise ParameterError(f"{where}.origin[2]: {oz} must be the flange top ({flange_top:g}) plus the bottom "
                             f"standoffs' length ({keys.text('bottom')}: {bottom.num('length'):g})")
    if abs(pitch - (between.num("length") + thickness)) > 1e-6:
        raise ParameterError(f"{where}.stack_pitch: {pitch} must be a standoff length plus the board thickness: "
                             f"{keys.text('between')} gives {between.num('length') + thickness:g}")
    if bottom.num("stud_length") > flange:
        raise ParameterError(f"{where}.standoffs.bottom: the {bottom.num('stud_length'):g} mm stud of "
                             f"{keys.text('bottom')} sticks out of the {flange:g} mm flange")
    depth = {role: node.num("length") - purchased.STUD_WEB for role, node in (("bottom", bottom), ("between", between))}
    reaches = [("between", between.num("stud_length") - thickness, min(depth.values())),
               ("screw", screw.num("length") - thickness, depth["between" if count > 1 else "bottom"])]
    for role, reach, room in reaches:
        if not 2 * screw.num("diameter") / 3 <= reach <= room:   # engage at least two thirds of a diameter
            raise ParameterError(f"{where}.standoffs.{role}: reaches {reach:g} mm past the board into a "
                                 f"{room:g} mm deep female thread")
    for x, y in hole_positions(params):
        probe = geom.cyl("z", bottom.num("thread"), -1, pcb + 1, (x, y))
        if board.pcb.intersect(probe).Volume() > 1e-6 or abs(x) > board.size[0] / 2 or abs(y) > board.size[1] / 2:
            raise ParameterError(f"{where}.mounting_holes: {board.path.name} has no M3 hole at ({x:g}, {y:g})")

    parts: list[Part] = []
    for i, (x, y) in enumerate(hole_positions(params)):
        parts.append(purchased.standoff(params, f"board_standoff_0_{i}", keys.text("bottom"), "neck_base",
                                        loc(x, y, flange_top)))
        for level in range(1, count):
            parts.append(purchased.standoff(params, f"board_standoff_{level}_{i}", keys.text("between"), "neck_base",
                                            loc(x, y, oz + (level - 1) * pitch + thickness)))
        parts.append(purchased.screw(params, f"board_screw_{i}", screw_key, "neck_base",
                                     loc(x, y, oz + (count - 1) * pitch + thickness, rx=180)))
    return parts
