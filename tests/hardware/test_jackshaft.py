# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""One jackshaft module for every joint that needs a stage (robogene_head/parts/jackshaft.py): a stage whose frame
sits elsewhere in its link (the yaw's is to be turned to point down through the head floor) is the same stage moved
there, part by part and in the plate's cut-outs, while each part's own frame, which its drawing is made in, stays
the stage's."""
import dataclasses

import numpy as np
import pytest

from robogene_head.geom import exact_bounds
from robogene_head.parts import jackshaft, tilt_jackshaft
from robogene_head.parts.base import loc

ELSEWHERE = loc(10, -20, 5, rz=30) * loc(rx=-90)


def _same(a, b) -> bool:
    (a0, a1), (b0, b1) = exact_bounds(a), exact_bounds(b)
    return (a.Volume() == pytest.approx(b.Volume(), rel=1e-9)
            and np.allclose(a0, b0, atol=1e-6) and np.allclose(a1, b1, atol=1e-6)
            and np.allclose(a.Center().toTuple(), b.Center().toTuple(), atol=1e-6))


@pytest.fixture(scope="module")
def stages(params):
    here = tilt_jackshaft.stage(params)
    assert here.placement is None   # the tilt's stage frame is the head frame
    return here, dataclasses.replace(here, placement=ELSEWHERE)


def test_a_stage_placed_elsewhere_is_the_same_stage_moved(params, stages):
    here, there = stages
    built = {p.name: p for p in jackshaft.build(params, here)}
    moved = {p.name: p for p in jackshaft.build(params, there)}
    assert list(moved) == list(built)
    wrong = [n for n in built if not _same(moved[n].shape, built[n].shape.moved(ELSEWHERE))]
    assert wrong == []
    # what each part is made or bought as does not change with where the stage stands
    assert [n for n in built if not _same(moved[n].local, built[n].local)] == []


def test_the_plate_is_cut_where_the_stage_stands(params, stages):
    here, there = stages
    tools = jackshaft.plate_tools(params, here)
    placed = jackshaft.plate_tools(params, there)
    assert len(placed) == len(tools) > 0
    assert all(_same(p, t.moved(ELSEWHERE)) for p, t in zip(placed, tools))


def test_a_misplaced_stage_is_told_apart(params, stages):
    """The comparison sees a stage moved by the wrong placement (the frames composed the other way round)."""
    here, _ = stages
    built = {p.name: p for p in jackshaft.build(params, here)}
    housing = built["eyes_tilt_jackshaft_housing"].shape
    assert not _same(housing.moved(loc(rx=-90) * loc(10, -20, 5, rz=30)), housing.moved(ELSEWHERE))
