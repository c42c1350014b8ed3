# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Every part is one valid, closed solid; the check rejects shapes that are not."""
import cadquery as cq

from robogene_head import geom
from robogene_head.checks import validity
from robogene_head.parts import Part


def test_every_part_is_one_valid_solid(assembly):
    bad = [c for c in validity.check_all(assembly.parts) if not c.ok]
    assert bad == []
    kinds = {p.kind for p in assembly.parts}
    assert kinds == {"machined", "printed", "purchased", "board"}


def test_two_solids_in_one_part_are_rejected():
    two = cq.Compound.makeCompound([geom.box(0, 1, 0, 1, 0, 1), geom.box(3, 4, 0, 1, 0, 1)])
    result = validity.check_part(Part("two", "two", "neck_base", "machined", two, material="aluminium-6082"))
    assert result.solids == 2 and not result.ok


def test_an_open_shell_is_rejected():
    box = geom.box(0, 1, 0, 1, 0, 1)
    open_shell = cq.Shell.makeShell(box.Faces()[:5])
    result = validity.check_part(Part("open", "open", "neck_base", "machined", open_shell, material="aluminium-6082"))
    assert not result.ok


def test_a_board_must_have_one_solid_per_material():
    pieces = [geom.box(0, 1, 0, 1, 0, 1), geom.box(3, 4, 0, 1, 0, 1)]
    board = Part("b", "b", "neck_base", "board", cq.Compound.makeCompound(pieces),
                 solid_materials=("pcb-fr4-4-layer", "board-components"))
    assert validity.check_part(board).ok
    short = Part("b", "b", "neck_base", "board", cq.Compound.makeCompound(pieces), solid_materials=("pcb-fr4-4-layer",))
    result = validity.check_part(short)
    assert (result.solids, result.expected_solids) == (2, 1) and not result.ok
