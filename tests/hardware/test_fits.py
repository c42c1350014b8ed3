# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""ISO 286 fits: the limit deviations against the standard's tables, the seats the build finds in the assembly,
and the fits read back from the drawings the package holds (PDF and SVG)."""
import json
import re

import pytest
import yaml

from robogene_head import fits
from robogene_head_model.params import DEFAULT_PATH, ParameterError, load
from test_drawings import pdf_text, svg_text


@pytest.mark.parametrize("diameter, tolerance, upper, lower", [
    (19, "H7", 0.021, 0.0), (24, "M7", 0.0, -0.021), (6, "H7", 0.012, 0.0), (10, "k6", 0.010, 0.001),
    (6, "k6", 0.009, 0.001), (15, "h6", 0.0, -0.011), (10, "g6", -0.005, -0.014), (10, "js6", 0.0045, -0.0045),
    (3, "H7", 0.010, 0.0), (30, "k6", 0.015, 0.002),
])
def test_limit_deviations_are_iso_286(diameter, tolerance, upper, lower):
    assert fits.deviations(diameter, tolerance) == (pytest.approx(upper, abs=1e-9), pytest.approx(lower, abs=1e-9))


@pytest.mark.parametrize("diameter, tolerance, message", [
    (40, "H7", "beyond the table"), (10, "k5", "grade must be one of"), (10, "x6", "letter 'x' is not in the table"),
])
def test_a_fit_outside_the_table_is_refused(diameter, tolerance, message):
    with pytest.raises(ValueError, match=message):
        fits.deviations(diameter, tolerance)


@pytest.fixture(scope="module")
def found(params, assembly):
    return fits.find(params, assembly.parts)


@pytest.mark.timeout(900)
def test_every_bearing_has_its_seat_and_journal(params, assembly, found):
    """Each bearing of the assembly is held by one housing seat and one journal, with the fit its ring needs. On
    pitch and roll the gearhead's own output bearings are the fixed bearing: the one ball bearing there floats in
    the right upright and in the front lug, on the stage's one journal."""
    roles = {(f.design, f.role, f.tolerance, f.count) for fs in found.values() for f in fs}
    assert ("neck_upright_bearing", "housing", "H7", 1) in roles and "neck_upright_drive" not in found
    assert ("neck_pitch_stage", "journal", "k6", 1) in roles
    assert ("neck_pitch_front_lug", "housing", "H7", 1) in roles and ("neck_roll_stage", "journal", "k6", 1) in roles
    assert not any(f.role == "housing" for f in found.get("neck_pitch_stage", []))
    # yaw: two bearings in the floor's boss on the fixed shaft, a pair of seats and a pair of journals
    assert ("head_floor", "housing", "M7", 2) in roles and ("neck_roll_stage", "journal", "h6", 2) in roles
    assert ("eyes_tilt_frame", "journal", "k6", 2) in roles
    assert {("head_side_plate_left", "housing", "H7", 1), ("head_side_plate_right", "housing", "H7", 1)} <= roles
    catalog = params.root.node("purchased")
    bearings = [p for p in assembly.parts if p.kind == "purchased" and catalog.has(p.design)
                and params.purchased(p.design).text("kind") == "bearing"]
    housings = sum(f.count for fs in found.values() for f in fs if f.role == "housing")
    assert housings == len(bearings)
    for fs in found.values():
        for f in fs:
            assert (f.coaxial > 0) == (f.count == 2)


@pytest.mark.timeout(900)
def test_the_fit_choice_comes_from_the_parameters(params, assembly, tmp_path):
    data = yaml.safe_load(DEFAULT_PATH.read_text())
    data["fits"]["journal_turning_ring"] = "js6"
    path = tmp_path / "p.yaml"
    path.write_text(yaml.safe_dump(data))
    changed = fits.find(load(path), assembly.parts)
    assert "⌀10 js6 (+0.0045/-0.0045) bearing journal" in fits.note(changed["neck_roll_stage"])
    data["fits"]["journal_turning_ring"] = "k5"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ParameterError, match=r"fits\.journal_turning_ring: tolerance 'k5': grade must be one of"):
        fits.find(load(path), assembly.parts)


def _flat(text: str) -> str:
    return re.sub(r"\s+", " ", text)


@pytest.mark.timeout(900)
def test_the_drawings_print_the_fits(fab, found):
    """Every fitted part's drawing carries its fits line, on the PDF and on the SVG, and the package's report
    lists the same fits the assembly has."""
    report = json.loads((fab / "reports" / "fits.json").read_text())
    assert sorted(report) == sorted(found)
    for design, fs in found.items():
        assert [r["text"] for r in report[design]] == [f.text() for f in fs]
        for text in (pdf_text(fab / "drawings" / f"{design}.pdf"), svg_text(fab / "drawings" / f"{design}.svg")):
            flat = _flat(text)
            assert "FITS ISO 286:" in flat, design
            for f in fs:
                assert _flat(f.text()) in flat, (design, f.text())
