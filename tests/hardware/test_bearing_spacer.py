# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The floating bearings' retaining rings stand off the bearings by a shim ring: a DIN 472 ring's lugs reach in over
the 61800's inner ring, which turns while the ring stands still. The seat refuses a design without the shim, with a
shim too thin to hold them off, or with one whose bore rubs the inner ring."""
import pytest

from robogene_head_model.params import ParameterError
from robogene_head.parts import neck
from robogene_head.geom import distance

from param_variants import edited


@pytest.fixture(scope="module")
def neck_parts(params):
    return {p.name: p.shape for p in neck.build(params)}


@pytest.mark.parametrize("bearing, host", [("neck_pitch_bearing_right", "neck_upright_right"),
                                           ("neck_roll_bearing_front", "neck_pitch_front_lug")])
def test_the_ring_stands_off_the_bearing_on_the_shim(params, neck_parts, bearing, host):
    stem = bearing.rsplit("_", 1)[0]
    ring, shim = neck_parts[f"{stem}_ring"], neck_parts[f"{stem}_spacer"]
    thickness = params.purchased(neck.spacer(params)).num("thickness")
    assert distance(ring, neck_parts[bearing]) == pytest.approx(thickness)
    assert thickness >= neck.LUG_GAP
    assert distance(ring, shim) < 1e-6 and distance(shim, neck_parts[bearing]) < 1e-6
    for part in (ring, shim):
        assert part.intersect(neck_parts[host]).Volume() < 1e-3


def _drop_spacer(d):
    del d["geometry"]["bearing_seats"]["spacer"]


@pytest.mark.parametrize("edit, message", [
    (_drop_spacer, r"geometry\.bearing_seats\.spacer: the din472-19x1 ring's lugs reach in to 11, over the neck_pitch "
                   r"bearing's inner ring \(12\.5 across\).*\(this one: 0\)"),
    (lambda d: d["purchased"]["din988-13x19x0.5"].update(thickness=0.1), r"at least 0\.3 thick.*this one: 0\.1"),
    (lambda d: d["purchased"]["din988-13x19x0.5"].update(bore=12), r"must fit the 19 mm bore and clear"),
])
def test_a_ring_that_can_rub_the_inner_ring_is_refused(tmp_path, edit, message):
    with pytest.raises(ParameterError, match=message):
        neck.build(edited(tmp_path, edit))


def test_a_bearing_whose_inner_ring_the_lugs_clear_needs_no_shim(tmp_path):
    def edit(d):
        _drop_spacer(d)
        d["purchased"]["skf-61800-2RS"].update(inner_ring_outside=10.5)
    names = {p.name for p in neck.build(edited(tmp_path, edit))}
    assert "neck_pitch_bearing_ring" in names and "neck_pitch_bearing_spacer" not in names
