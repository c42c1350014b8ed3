# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The eyes' stereo budget term by term (robogene_head/eye_accuracy.py, eye_error_terms.py) against closed-form
numbers: today's spur gearheads miss it, a zero-backlash gear with its stiffness published is counted term by term,
and the hard stop's homing enters through the lug it bends."""
import json
import math

import pytest

from robogene_head import eye_accuracy, eye_error_terms
from robogene_head_model.params import ParameterError

from param_variants import edited

PEAK = {"left_eye_pan": 0.001, "right_eye_pan": 0.001}      # N m, about what drive sizing gives the pans
PER_RAD = (500 ** 2 + 34 ** 2) / 68                         # mm of depth per radian of vergence at 0.5 m, 68 mm apart
KT = 12 / (12800 * 2 * math.pi / 60)                        # the 1717T012SR: 12 V over its no-load speed
HOMING_A = 0.1                  # motor_control.homing.eyes_version.current_limit: the eyes press their stops at 100 mA


def _terms(e):
    return {t.name: t for t in e.terms}


def test_depth_per_vergence_is_the_derivative_of_the_geometry():
    """Z(g) = (B/2) / tan(g/2): the slope dZ/dg at the vergence that fixates 500 mm."""
    b, z = 68.0, 500.0
    g = 2 * math.atan(b / 2 / z)
    h = 1e-7
    slope = ((b / 2) / math.tan((g - h) / 2) - (b / 2) / math.tan((g + h) / 2)) / (2 * h)
    assert eye_accuracy.depth_per_vergence(b, z) == pytest.approx(slope, rel=1e-6)


def test_the_lug_is_a_cantilever_from_the_cup_to_the_pin():
    """Cup R19, lug at r14 3 x 3, plate 1 below the cup, lug 1.5 above it, pin 8 long pressed 4 deep: the lug
    leaves the cup at z = -sqrt(19^2 - 14^2), the load acts halfway between its bottom (-18.5) and the pin's top
    (-16), and a torque T pushes T / 14 on it."""
    from robogene_head_model.params import load
    params = load()
    lever = math.sqrt(19 ** 2 - 14 ** 2) * -1 + 17.25
    e, nu = 1500.0, 0.4
    per_newton = lever ** 3 / (3 * e * 3 * 3 ** 3 / 12) + lever / (5 / 6 * e / (2 * (1 + nu)) * 9)
    assert eye_error_terms.stop_compliance(params) == pytest.approx(per_newton / 14 ** 2 * 1000, rel=1e-9)


def test_a_stiffer_lug_bends_less(tmp_path):
    from robogene_head_model.params import load
    base = eye_error_terms.stop_compliance(load())
    stiff = edited(tmp_path, lambda d: d["eye_accuracy"].update(stop_modulus_MPa=3000))
    assert eye_error_terms.stop_compliance(stiff) == pytest.approx(base / 2, rel=1e-9)


def test_todays_spur_gearheads_miss_the_budget(params):
    """The 16/7's 2 deg of backlash alone is 50 times the budget, and FAULHABER publishes neither its
    hysteresis nor its stiffness: the report says so, and the check refuses the drive."""
    e = eye_accuracy.budget(params, PEAK)
    assert e.vergence_allowed_deg == pytest.approx(math.degrees(5 / PER_RAD), rel=1e-9)
    assert e.per_eye_allowed_deg == pytest.approx(e.vergence_allowed_deg / 2)
    t = _terms(e)
    assert t["backlash"].deg == 2.0 and not t["backlash"].repeatable
    assert t["quantisation"].deg == pytest.approx(360 / (4 * 512 * 43))
    assert t["transmission"].deg is None and t["transmission"].repeatable
    assert e.unknown == ["hysteresis", "wind_up", "home_spread"]
    assert e.per_eye_deg is None and not e.ok
    home = KT * HOMING_A * 43 * 0.7                         # homing current limit x kt x ratio x efficiency
    lug = math.degrees(home * eye_error_terms.stop_compliance(params))
    assert t["stop_offset"].deg == pytest.approx(lug) and t["stop_offset"].repeatable
    assert t["stop_spread"].deg == pytest.approx(0.2 * lug + t["quantisation"].deg)
    known = 2.0 + t["quantisation"].deg + t["stop_spread"].deg
    assert e.known_per_eye_deg == pytest.approx(known)
    assert e.depth_mm == pytest.approx(PER_RAD * math.radians(2 * known))
    with pytest.raises(eye_accuracy.EyeAccuracyError, match=r"(?s)unknown: hysteresis, wind_up, home_spread.*"
                                                            r"does NOT meet it"):
        eye_accuracy.enforce(e)


def _strain_wave(d, hysteresis=1.0):
    """The 16/7's place taken by a size-5 strain-wave gear, 1:50, with the RSF-5B's published stiffness (T1
    0.075 N m, K1 110, K2 140 N m/rad) and one-way accuracy (3 arc-min); the hysteresis is a test input."""
    d["purchased"]["faulhaber-16-7-43"].update(
        ratio=50, backlash_deg=0, transmission_accuracy_arcmin=3, hysteresis_loss_arcmin=hysteresis,
        torsional_stiffness={"T1": 0.075, "K1": 110, "K2": 140})


def test_a_strain_wave_gear_is_counted_term_by_term(tmp_path):
    params = edited(tmp_path, _strain_wave)
    e = eye_accuracy.budget(params, PEAK)
    t = _terms(e)
    assert e.unknown == []
    assert t["transmission"].deg == pytest.approx(3 / 60) and t["transmission"].repeatable
    assert t["hysteresis"].deg == pytest.approx(1 / 60)
    assert t["wind_up"].deg == pytest.approx(math.degrees(0.001 / 110))
    home = KT * HOMING_A * 50 * 0.7                         # below T1: on K1 alone
    assert home < 0.075
    assert t["home_wind_up"].deg == pytest.approx(math.degrees(home / 110))
    assert t["home_spread"].deg == pytest.approx(0.2 * t["home_wind_up"].deg)
    counted = sum(x.deg for x in e.terms if not x.repeatable)
    assert e.per_eye_deg == pytest.approx(counted)
    assert e.uncalibrated_deg == pytest.approx(sum(x.deg for x in e.terms))


def _homing_current(d, ma):
    d["motor_control"]["homing"]["eyes_version"]["current_limit"] = ma


def _budget_terms(tmp_path, name, edit):
    (tmp_path / name).mkdir()
    return _terms(eye_accuracy.budget(edited(tmp_path / name, edit), PEAK))


def test_the_stop_terms_follow_the_homing_current_not_the_run_limit(tmp_path):
    """The stall torque at the stop is the homing run's current limit through the gear: the lug's bending scales
    with it, while the joints' run limit (what the drive sizing counts on) does not enter."""
    base = _budget_terms(tmp_path, "base", _strain_wave)
    tripled = _budget_terms(tmp_path, "300", lambda d: (_strain_wave(d), _homing_current(d, 300)))
    assert tripled["stop_offset"].deg == pytest.approx(3 * base["stop_offset"].deg)
    assert "(300 mA)" in tripled["stop_offset"].what and "(100 mA)" in base["stop_offset"].what

    def run_limit(d):
        _strain_wave(d)
        for j in ("eyes_version", "eyes_vergence"):
            d["motor_control"]["joints"][j]["current_limit"] = 900
    raised = _budget_terms(tmp_path, "run", run_limit)
    for name in ("stop_offset", "stop_spread", "home_wind_up", "home_spread"):
        assert raised[name].deg == pytest.approx(base[name].deg), name


def test_a_homing_current_above_the_run_limit_counts_as_the_run_limit(tmp_path):
    """As the firmware does (the lower of the two holds the motors), so does the budget."""
    at_run = _budget_terms(tmp_path, "600", lambda d: (_strain_wave(d), _homing_current(d, 600)))
    above = _budget_terms(tmp_path, "5000", lambda d: (_strain_wave(d), _homing_current(d, 5000)))
    assert above["stop_offset"].deg == pytest.approx(at_run["stop_offset"].deg)
    assert above["home_wind_up"].deg == pytest.approx(at_run["home_wind_up"].deg)


def test_homing_at_the_run_limit_spends_the_budget(tmp_path):
    """The broken variant: the same gear pressed onto the printed lug with the run limit (600 mA), as before the
    homing run had a limit of its own: the stall's spread alone is more than the budget, and the check refuses it."""
    e = eye_accuracy.budget(edited(tmp_path, lambda d: (_strain_wave(d, hysteresis=0.5), _homing_current(d, 600))),
                            PEAK)
    t = _terms(e)
    home = KT * 0.6 * 50 * 0.7
    assert t["home_wind_up"].deg == pytest.approx(math.degrees(0.075 / 110 + (home - 0.075) / 140))
    assert t["stop_spread"].deg + t["home_spread"].deg > e.per_eye_allowed_deg and not e.ok
    with pytest.raises(eye_accuracy.EyeAccuracyError, match="does NOT meet it"):
        eye_accuracy.enforce(e)


def test_homing_gently_with_a_zero_backlash_gear_meets_it(tmp_path):
    """The same gear homed with the parameter file's homing current (100 mA) leaves the stop's spread small
    enough: the check passes, and the report says so."""
    e = eye_accuracy.budget(edited(tmp_path, lambda d: _strain_wave(d, hysteresis=0.5)), PEAK)
    assert e.ok and e.depth_mm < 5
    eye_accuracy.enforce(e)
    assert "the drive meets it" in eye_accuracy.format_report(e)


def test_a_torque_beyond_T1_needs_K2(tmp_path):
    params = edited(tmp_path, lambda d: (_strain_wave(d), _homing_current(d, 600),
                                         d["purchased"]["faulhaber-16-7-43"]["torsional_stiffness"].pop("K2")))
    with pytest.raises(ParameterError, match=r"purchased\.faulhaber-16-7-43\.torsional_stiffness\.K2: missing: "
                                             r"0\.188 N m is beyond T1 = 0\.075 N m"):
        eye_accuracy.budget(params, PEAK)


def test_only_hard_stop_homing_is_budgeted(tmp_path):
    params = edited(tmp_path, lambda d: d["homing"]["left_eye_pan"].update(method="absolute_encoder"))
    with pytest.raises(ParameterError, match=r"homing\.left_eye_pan\.method: the eye budget counts hard_stop homing "
                                             r"only, got 'absolute_encoder'"):
        eye_accuracy.budget(params, PEAK)


def test_the_package_reports_every_term(params, fab):
    """The report in the package is the budget of the pans' peak torques from the package's own drive sizing."""
    sizing = json.loads((fab / "reports" / "drive-sizing.json").read_text())
    loads = {j["joint"]: j["load_Nm"] for j in sizing["joints"]}
    expected = json.loads(eye_accuracy.dumps(eye_accuracy.budget(params, loads)))
    assert json.loads((fab / "reports" / "eye-accuracy.json").read_text()) == expected
    text = (fab / "reports" / "eye-accuracy.txt").read_text()
    for term in expected["terms"]:
        assert f"  {term['name']} " in text


@pytest.mark.parametrize("edit, message", [
    (lambda d: d["eye_accuracy"].update(homing_torque_spread=1.5), r"eye_accuracy\.homing_torque_spread: must be <= 1"),
    (lambda d: d["eye_accuracy"].update(stop_modulus_MPa=0), r"eye_accuracy\.stop_modulus_MPa: must be > 0"),
    (lambda d: d["purchased"]["faulhaber-16-7-43"].update(torsional_stiffness=110),
     r"purchased\.faulhaber-16-7-43\.torsional_stiffness: expected a mapping"),
    (lambda d: d["purchased"]["faulhaber-16-7-43"].update(hysteresis_loss_arcmin="1'"),
     r"purchased\.faulhaber-16-7-43\.hysteresis_loss_arcmin: expected a number"),
    (lambda d: d["motor_control"]["homing"]["eyes_version"].pop("current_limit"),
     r"motor_control\.homing\.eyes_version\.current_limit: missing"),
    (lambda d: _homing_current(d, 0), r"motor_control\.homing\.eyes_version\.current_limit: must be > 0"),
    (lambda d: d["motor_control"].pop("homing"), r"motor_control\.homing: missing"),
])
def test_bad_budget_input_is_named(tmp_path, edit, message):
    with pytest.raises(ParameterError, match=message):
        eye_accuracy.budget(edited(tmp_path, edit), PEAK)
