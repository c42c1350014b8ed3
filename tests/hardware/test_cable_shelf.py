# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The camera cables' shelf (robogene_head/parts/cable_shelf.py): a printed angle of its own on the tilt link, its
foot on the tilt plate's back edge between the eyes, held by two screws from above through clearance holes in the
foot into the plate's tapped holes, its wall behind the eyes where the camera cables' clamps are; bad parameters are
named."""
import numpy as np
import pytest

from robogene_head import geom
from robogene_head.parts import eyes
from robogene_head_model.params import ParameterError

from param_variants import edited


@pytest.fixture(scope="module")
def tilt_parts(params):
    return {p.name: p for p in eyes.build(params)}


def _common(a, b) -> float:
    """mm^3 the two solids share."""
    return a.intersect(b).Volume()


def test_the_shelf_is_its_own_part_on_the_plate(params, tilt_parts):
    shelf, frame = tilt_parts["eyes_cable_shelf"], tilt_parts["eyes_tilt_frame"]
    assert shelf.link == frame.link == "eyes_tilt_link" and shelf.kind == "printed"
    (x0, y0, z0), (x1, y1, z1) = geom.exact_bounds(shelf.shape)
    (fx0, _, fz0), _ = geom.exact_bounds(frame.shape)
    s = params.geometry("eyes", "tilt_frame").node("cable_shelf")
    back = fx0                                       # the plate's back edge is the frame's rearmost face
    assert x0 == pytest.approx(back - s.num("depth")) and x1 == pytest.approx(back + s.num("overlap"))
    assert z1 - z0 == pytest.approx(s.num("wall_height"))
    assert (y0, y1) == (pytest.approx(-s.num("width") / 2), pytest.approx(s.num("width") / 2))
    # the foot bears on the plate's top, not into it
    assert geom.distance(shelf.shape, frame.shape) == pytest.approx(0, abs=1e-6)
    assert _common(shelf.shape, frame.shape) == pytest.approx(0, abs=1e-6)


def test_two_screws_from_above_through_the_foot_into_the_plate(params, tilt_parts):
    shelf, frame = tilt_parts["eyes_cable_shelf"], tilt_parts["eyes_tilt_frame"]
    screws = [p for n, p in tilt_parts.items() if n.startswith("eyes_cable_shelf_screw_")]
    assert len(screws) == 2 and {p.link for p in screws} == {"eyes_tilt_link"}
    for screw in screws:
        # its head bears on the foot, its shank passes the foot's clearance hole and fills the plate's tapped hole
        # (drawn at the thread), its tip no lower than the plate's underside
        assert _common(screw.shape, frame.shape) == pytest.approx(0, abs=1e-3)
        assert geom.distance(screw.shape, frame.shape) == pytest.approx(0, abs=1e-6)
        assert _common(screw.shape, shelf.shape) == pytest.approx(0, abs=1e-3)
        assert geom.distance(screw.shape, shelf.shape) == pytest.approx(0, abs=1e-6)
        (_, _, tip), _ = geom.exact_bounds(screw.shape)
        (_, _, plate_bottom), _ = geom.exact_bounds(frame.shape.intersect(geom.box(-12.5, -11.5, -1, 1, -50, 50)))
        assert tip >= plate_bottom - 1e-6


@pytest.mark.parametrize("change, message", [
    ({"width": 120}, r"cable_shelf\.width: 120 reaches the tilt frame's arms"),
    ({"wall": 35}, r"cable_shelf\.wall: 35 leaves no foot behind the plate"),
    ({"screw_y": 19}, r"cable_shelf\.screw_y: 19 puts the screws off the 36 mm foot"),
    ({"screw": "iso4762-M2x10"}, r"cable_shelf\.screw: iso4762-M2x10 \(10 long\) would stand out under the plate"),
    ({"depth": -5}, r"cable_shelf\.depth: must be > 0"),
])
def test_bad_shelf_parameters_are_named(tmp_path, change, message):
    def edit(d):
        d["geometry"]["eyes"]["tilt_frame"]["cable_shelf"].update(change)
    with pytest.raises(ParameterError, match=message):
        eyes.build(edited(tmp_path, edit))
