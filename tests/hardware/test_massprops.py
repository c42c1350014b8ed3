# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Mass properties against closed-form results (a box and a cylinder of known density, placed and turned in
their link frame), and the package's head against the reference head, so that a units slip (mm vs m,
g vs kg) cannot pass."""
import json
import math

import numpy as np
import pytest

from robogene_head import geom, massprops
from robogene_head.parts import Part
from robogene_head.parts.base import loc


def _rz(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def _rx(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def test_box_of_aluminium(params):
    a, b, c = 20.0, 30.0, 40.0                     # mm
    rho = params.root.node("materials").num("aluminium-6082") * 1e-9   # kg/mm^3
    box = geom.box(-a / 2, a / 2, -b / 2, b / 2, -c / 2, c / 2)
    part = Part("box", "box", "neck_base", "machined", box, loc(5, -7, 11, rz=30), material="aluminium-6082")
    mp = massprops.part_props(params, part)
    m = 2700 * (a * b * c) * 1e-9                  # kg
    assert m == pytest.approx(0.0648)
    assert mp.mass == pytest.approx(m, rel=1e-9)
    assert mp.mass == pytest.approx(rho * a * b * c, rel=1e-9)
    assert np.allclose(mp.com, [5, -7, 11], atol=1e-9)
    body = np.diag([m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12])
    rot = _rz(30)
    assert np.allclose(mp.inertia, rot @ body @ rot.T, rtol=1e-9, atol=1e-9)
    assert mp.inertia[0, 0] == pytest.approx(m * (b * b + c * c) / 12 * 0.75 + m * (a * a + c * c) / 12 * 0.25)


def test_cylinder_of_steel_turned_about_x(params):
    r, h = 10.0, 50.0
    cyl = geom.cyl("z", 2 * r, 0, h)               # axis z, base at the origin
    part = Part("rod", "rod", "neck_base", "machined", cyl, loc(1, 2, 3, rx=90), material="steel")
    mp = massprops.part_props(params, part)
    m = 7850e-9 * math.pi * r * r * h
    assert mp.mass == pytest.approx(m, rel=1e-6)
    # rx=90 turns +z into -y: the centre is h/2 along -y from (1, 2, 3)
    assert np.allclose(mp.com, [1, 2 - h / 2, 3], atol=1e-6)
    body = np.diag([m * (3 * r * r + h * h) / 12, m * (3 * r * r + h * h) / 12, m * r * r / 2])
    rot = _rx(90)
    assert np.allclose(mp.inertia, rot @ body @ rot.T, rtol=1e-6, atol=1e-9)
    assert mp.inertia[1, 1] == pytest.approx(m * r * r / 2, rel=1e-6)   # the axis now lies along y


def test_purchased_envelope_carries_its_datasheet_mass(params):
    key = "skf-626-2Z"
    from robogene_head.parts import purchased
    part = purchased.bearing(params, "b", key, "neck_base", loc(0, 0, 10))
    mp = massprops.part_props(params, part)
    assert mp.mass == pytest.approx(params.purchased(key).num("mass"), rel=1e-9)
    assert np.allclose(mp.com, [0, 0, 10 + params.purchased(key).num("width") / 2], atol=1e-9)


def test_two_halves_combine_to_the_whole_box(params):
    whole = massprops.part_props(params, Part("w", "w", "neck_base", "machined", geom.box(0, 40, 0, 10, 0, 10),
                                              material="aluminium-6082"))
    halves = [massprops.part_props(params, Part(n, n, "neck_base", "machined", geom.box(x0, x0 + 20, 0, 10, 0, 10),
                                                material="aluminium-6082")) for n, x0 in (("l", 0), ("r", 20))]
    both = massprops.combine(halves)
    assert both.mass == pytest.approx(whole.mass)
    assert np.allclose(both.com, whole.com)
    assert np.allclose(both.inertia, whole.inertia, rtol=1e-9, atol=1e-12)


def test_a_part_of_two_materials_weighs_each_solid_by_its_own(params):
    pcb, comp = geom.box(-45, 45, -30, 30, 0, 1.6), geom.box(0, 10, 0, 10, 1.6, 4.6)
    import cadquery as cq
    part = Part("b", "b", "neck_base", "board", cq.Compound.makeCompound([pcb, comp]),
                solid_materials=("pcb-fr4-4-layer", "board-components"))
    mats = params.root.node("materials")
    expected = (90 * 60 * 1.6 * mats.num("pcb-fr4-4-layer") + 300 * mats.num("board-components")) * 1e-9
    assert massprops.part_props(params, part).mass == pytest.approx(expected, rel=1e-9)


def test_moved_turns_and_shifts_the_inertia():
    mp = massprops.MassProps(2.0, np.array([1.0, 0, 0]), np.diag([1.0, 2.0, 3.0]))
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = _rz(90), [0, 0, 5]
    out = mp.moved(m)
    assert np.allclose(out.com, [0, 1, 5])
    assert np.allclose(np.diag(out.inertia), [2.0, 1.0, 3.0])


def test_package_head_is_in_the_reference_heads_range(fab, params):
    """Within a factor of about two of the iCub 2.7 head (1.8606 kg; 7753.9, 7533.2, 5732.4 kg mm^2): a mass in
    grams or an inertia in kg m^2 would be off by 1000 or 10^6."""
    report = json.loads((fab / "reports" / "mass.json").read_text())
    head, ref = report["head_above_yaw"], params.root.node("reference")
    assert ref.num("head_mass") == pytest.approx(1.8606)
    assert 0.5 < head["mass_kg"] / ref.num("head_mass") < 1.5
    ref_i = ref.node("head_inertia_kgmm2")
    for k, axis in enumerate(("xx", "yy", "zz")):
        assert 0.3 < head["inertia_kgmm2"][k][k] / ref_i.num(axis) < 2.0, axis
    # the centre of mass lies inside the head frame's box (mm): between floor and top, behind the face
    h = params.geometry("head")
    com = head["com_mm"]
    assert h.node("floor").num("x_min") < com[0] < h.node("side_plate").num("x_max")
    assert abs(com[1]) < h.node("floor").num("half_width")
    assert 0 < com[2] < h.node("side_plate").num("height")
    # the ratios the report gives are the ratios of its own numbers
    assert report["reference"]["mass_ratio"] == pytest.approx(head["mass_kg"] / ref.num("head_mass"), abs=1e-4)
