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

from param_variants import edited

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


def _flange_back(params, tmp_path, value, flange_half=None):
    def edit(d):
        h = d["geometry"]["tilt_jackshaft"]["housing"]
        h["flange_back"] = value
        if flange_half is not None:
            h["flange_half"] = flange_half
    variant = edited(tmp_path, edit)
    return jackshaft.housing(variant, tilt_jackshaft.stage(variant))


def test_the_flange_reaches_behind_the_axis_by_flange_back(params, tmp_path):
    """flange_back sets how far the housing's flange reaches behind the axis (the yaw's stands ahead of it only);
    the tilt's, the body's half, draws it from the body's back as before. Seen where the flange stands out above
    the body (a flange_half over the body's half, as the yaw's)."""
    from robogene_head import geom
    stage = tilt_jackshaft.stage(params)
    n = jackshaft.node(params, stage).node("housing")
    lay = jackshaft.layout(params, stage)
    assert n.num("flange_back") == n.num("half")
    half, wide = n.num("half"), n.num("half") + 5
    # a slab within the flange's thickness at the plate's inner face, above the body
    slab = geom.box(-1000, 1000, lay.inner - n.num("flange") / 2, lay.inner - 0.1, lay.z + half + 1, lay.z + wide - 1)
    for back in (half, 0.0, 4.0):
        housing = _flange_back(params, tmp_path, back, flange_half=wide)
        (x0, _, _), (x1, _, _) = exact_bounds(housing.intersect(slab))
        assert x0 == pytest.approx(lay.x - back, abs=1e-6)
        assert x1 == pytest.approx(lay.x + n.num("front"), abs=1e-6)


def test_a_flange_behind_the_body_is_refused(params, tmp_path):
    from robogene_head_model.params import ParameterError
    with pytest.raises(ParameterError, match=r"tilt_jackshaft\.housing\.flange_back: 12 reaches behind the body"):
        _flange_back(params, tmp_path, 12)
