# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The jackshaft stages' clamp couplings, made here (robogene_head/parts/jackshaft.py, geometry.<stage>.coupling):
each half split through one wall and closed by a screw across the split, the halves parted by a relief cut, the
screw's thread tapped beyond the split deep enough for aluminium, the bores' ISO 286 fit on the drawing; and a
coupling that could not clamp (no thread left, a relief through the part, a split up to the seat) is refused."""
import cadquery as cq
import pytest

from robogene_head import fits, threads
from robogene_head.parts import jackshaft, tilt_jackshaft, yaw_jackshaft
from robogene_head_model.params import ParameterError

from param_variants import edited

STAGES = {"eyes_tilt": tilt_jackshaft, "neck_yaw": yaw_jackshaft}


def _inside(shape, x, y, z) -> bool:
    return shape.isInside(cq.Vector(x, y, z), 1e-6)


@pytest.mark.parametrize("joint", sorted(STAGES))
def test_each_half_is_split_and_the_halves_are_parted(params, joint):
    """In the coupling's frame (axis +z, the screws along -y at x = -offset): the split on y = 0 runs through the -x
    wall along the whole length, the relief cut at mid-length reaches 1 mm past the axis and no further."""
    stage = STAGES[joint].stage(params)
    c = jackshaft.coupling(params, stage)
    shape = jackshaft.coupling_shape(params, stage)
    length, d, large = c.num("length"), c.num("diameter"), c.vec("bores", 2)[1]
    wall = (large / 2 + d / 2) / 2                       # mid-wall radius
    for z in (1, length / 2 - 1, length / 2 + 1, length - 1):     # clear of the screw holes
        assert not _inside(shape, -wall, 0, z)          # the split
        assert _inside(shape, -wall, 0.6, z) and _inside(shape, wall, 0, z)
    depth = c.num("relief_depth")
    assert not _inside(shape, depth - 0.3, wall, length / 2) and not _inside(shape, -wall, wall / 2, length / 2)
    assert _inside(shape, depth + 0.3, wall, length / 2)  # the ligament that joins the halves


@pytest.mark.parametrize("joint", sorted(STAGES))
def test_the_screws_are_tapped_beyond_the_split_and_clear_before_it(params, joint):
    """threads.py finds each screw's thread in the wall beyond the split (the shank fills the hole there), 5 mm
    of it; the drawing gets them as M2 tapped holes of the made coupling's own design."""
    parts = STAGES[joint].build(params)
    tapped = threads.tapped_holes(params, parts)[f"{joint}_coupling"]
    assert len(tapped) == 2 and {h.thread for h in tapped} == {"M2"}
    c = jackshaft.coupling(params, STAGES[joint].stage(params))
    engaged = c.num("seat") - params.purchased(c.text("screw")).num("length")   # the tip, on the screw's axis
    assert -c.num("split") / 2 - engaged == pytest.approx(5.25)


def test_the_drawings_get_the_clamp_bores_fit(params):
    parts = tilt_jackshaft.build(params) + yaw_jackshaft.build(params)
    found = fits.find(params, parts)
    assert fits.note(found["eyes_tilt_coupling"]) == \
        "FITS ISO 286: ⌀3 H7 (+0.010/0) clamp bore; ⌀6 H7 (+0.012/0) clamp bore."
    assert [f.diameter for f in found["neck_yaw_coupling"]] == [4, 6]
    coupling = next(p for p in parts if p.name == "eyes_tilt_coupling")
    assert (coupling.kind, coupling.material) == ("machined", "aluminium-6082")


def _tilt(tmp_path, **fields):
    def edit(data):
        data["geometry"]["tilt_jackshaft"]["coupling"].update(fields)
    return edited(tmp_path, edit)


@pytest.mark.parametrize("fields, named", [
    ({"screw": "iso4762-M2x6"}, r"tilt_jackshaft\.coupling\.screw: iso4762-M2x6 reaches 3.2 mm into the thread"),
    ({"relief_depth": 7}, r"coupling\.relief_depth: 7 leaves under 2 mm"),
    ({"split": 2.5}, r"coupling\.split: 2.5 reaches the screw head's seat"),
    ({"bores": [6, 3]}, r"coupling\.bores: expected the gearhead's bore, then the jackshaft's"),
])
def test_a_coupling_that_cannot_clamp_is_refused(tmp_path, fields, named):
    variant = _tilt(tmp_path, **fields)
    with pytest.raises(ParameterError, match=named):
        jackshaft.coupling_shape(variant, tilt_jackshaft.stage(variant))


def test_a_clamp_bore_fit_the_table_lacks_is_named(tmp_path, params):
    def edit(data):
        data["fits"]["clamp_bore"] = "Z9"
    variant = edited(tmp_path, edit)
    with pytest.raises(ParameterError, match=r"fits\.clamp_bore: tolerance 'Z9'"):
        fits.find(variant, tilt_jackshaft.build(variant))
