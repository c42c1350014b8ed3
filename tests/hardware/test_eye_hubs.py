# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The eye pans' torque path as the CAD draws it against what torque_paths: says (the torque-path check rates the
data, so the two must describe one design): set screws of the declared size and count bearing on the gearhead's
shaft, a hub whose bore is that shaft, a head with the declared flats and height sitting in the cup's matching
pocket; and hubs that cannot be built are refused by name."""
import pytest
import yaml

from robogene_head import geom
from robogene_head.parts import eye_hubs, eyes
from robogene_head.geom import distance
from robogene_head_model.params import ParameterError

from param_variants import edited

PANS = (("left", "left_eye_pan"), ("right", "right_eye_pan"))


def _entries(params, joint):
    raw = yaml.safe_load(params.path.read_text())["torque_paths"][joint]
    return {e["element"]: e for e in raw}


@pytest.fixture(scope="module")
def placed(assembly):
    return {p.part.name: p for p in assembly.pose(chain={})}


@pytest.mark.timeout(900)
@pytest.mark.parametrize("side, joint", PANS)
def test_the_set_screws_the_data_rates_bear_on_the_gearhead_shaft(params, placed, side, joint):
    screws = _entries(params, joint)["set_screw"]
    drawn = sorted(n for n in placed if n.startswith(f"{side}_eye_hub_set_screw_"))
    assert len(drawn) == screws["count"]
    shaft = placed[f"{joint}_gearhead"].shape
    hub = placed[f"{side}_eye_hub"].shape
    for name in drawn:
        p = placed[name]
        assert p.part.design == screws["screw"]
        # the point touches the shaft and does not cut into it; the screw sits in the hub's tapped hole
        assert distance(p.shape, shaft) < 0.01
        assert p.shape.intersect(shaft).Volume() < 1e-3
        assert distance(p.shape, hub) < 0.01 and p.shape.intersect(hub).Volume() < 1e-3


@pytest.mark.timeout(900)
@pytest.mark.parametrize("side, joint", PANS)
def test_the_hub_is_the_flats_the_data_rates(params, placed, side, joint):
    flat = _entries(params, joint)["d_flat"]
    hub = placed[f"{side}_eye_hub"].shape
    shaft = placed[f"{joint}_gearhead"].shape
    # the bore is the shaft: they touch all round without overlapping
    assert distance(hub, shaft) < 0.01 and hub.intersect(shaft).Volume() < 1e-3
    # the head: everything of the hub above the shaft's end, measured on its exact box in the eye's frame
    local = placed[f"{side}_eye_hub"].part.local
    lo, hi = geom.exact_bounds(local)
    _, shaft_end, top = eye_hubs.levels(params, -params.geometry("eyes").num("cup_radius")
                                        - params.geometry("eyes").num("gap"))
    head = local.intersect(geom.box(lo[0] - 1, hi[0] + 1, lo[1] - 1, hi[1] + 1, shaft_end, hi[2] + 1))
    hlo, hhi = geom.exact_bounds(head)
    assert hhi[0] - hlo[0] == pytest.approx(flat["shaft"], abs=1e-3)                      # round across x
    assert (flat["shaft"] - (hhi[1] - hlo[1])) / 2 == pytest.approx(flat["depth"], abs=1e-3)   # the flats on +-y
    assert hhi[2] - hlo[2] == pytest.approx(flat["length"], abs=1e-3)
    assert flat["flats"] == 2
    # the cup's pocket holds the head's flats: touching, not overlapping
    cup = placed[f"{side}_eye_cup"].shape
    assert distance(hub, cup) < 0.01 and hub.intersect(cup).Volume() < 1e-3


@pytest.mark.parametrize("hub, where", [
    ({"neck_diameter": 10}, r"geometry\.eyes\.hub\.neck_diameter: 10 leaves a 3\.5 mm wall"),
    ({"head_height": 6}, r"geometry\.eyes\.hub\.head_height: the hub's head reaches"),
    ({"gap": 2.5}, r"geometry\.eyes\.hub\.gap: the neck holds only 1\.50 mm"),
    ({"flat_depth": 6}, r"geometry\.eyes\.hub\.flat_depth: 6 on a 12 mm head"),
])
def test_a_hub_that_cannot_be_built_is_named(tmp_path, hub, where):
    params = edited(tmp_path, lambda d: d["geometry"]["eyes"]["hub"].update(hub))
    with pytest.raises(ParameterError, match=where):
        eyes.build(params)
