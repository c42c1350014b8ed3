# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The picture code itself, on a few neck parts: a warm fab build reuses cached pictures and never runs it, so a
broken renderer would otherwise only show on a fresh build. Each picture has its size and its own background."""
from pathlib import Path

import pytest
import vtk

from robogene_head import render, render_steps, sequence
from robogene_head.assembly import Assembly
from robogene_head.parts import neck

PARTS = ("neck_pitch_stage", "neck_roll_stage", "neck_roll_bearing_front")


@pytest.fixture(scope="module")
def small(params):
    wanted = [p for p in neck.build(params) if p.name in PARTS]
    return Assembly(params, wanted)


def _png(path: Path):
    reader = vtk.vtkPNGReader()
    reader.SetFileName(str(path))
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    top_left = scalars.GetTuple(scalars.GetNumberOfTuples() - width)     # VTK images start at the bottom row
    return (width, height), [round(c / 255, 2) for c in top_left[:3]]


def test_each_step_is_drawn_on_the_step_background(params, small, tmp_path):
    steps = [{"name": "pitch stage", "parts": ["neck_pitch_stage"], "fixture": True},
             {"name": "roll stage", "parts": ["neck_roll_stage"], "from": [[60, 0, 0]]},
             {"name": "roll bearing", "parts": ["neck_roll_bearing_front"], "from": [[20, 0, 0]]}]
    seq = sequence.parse({"drivers": {}, "screw_drivers": {}, "subassemblies": {}, "sequence": steps},
                         Path("small.yaml"), list(PARTS))
    pictures = render_steps.render_all(small, seq, tmp_path)
    assert [p.name for p in pictures] == [s.picture(i + 1) for i, s in enumerate(seq.steps())]
    for picture in pictures:
        size, corner = _png(picture)
        assert size == render_steps.SIZE
        assert corner == pytest.approx(render_steps.STEP_BACKGROUND[1], abs=0.02)


def test_a_view_is_drawn_on_the_packages_background(small, tmp_path):
    target = tmp_path / "view.png"
    render.render(small, render.View("small", {}, 35, 15), target, size=(160, 120))
    size, corner = _png(target)
    assert size == (160, 120)
    assert corner == pytest.approx(render.BACKGROUND[1], abs=0.02)
