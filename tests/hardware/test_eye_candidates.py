# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The eye-pan drive trade study (docs/fabricate.md, "Eyes for stereo"): each candidate's published figures put
through the real budget (robogene_head/eye_accuracy.py) on an edited parameter file, asserting the outcome the
docs' table states, so the table cannot drift from the code; and the room the eye module leaves a candidate,
measured in the assembly over the tilt's range. The pans' drive in the parameter file is not changed."""
import math

import numpy as np
import pytest

from robogene_head import eye_accuracy, geom
from robogene_head_model.params import ParameterError

from param_variants import edited

PEAK = {"left_eye_pan": 0.001, "right_eye_pan": 0.001}      # N m, about what drive sizing gives the pans
PANS = ("left_eye_pan", "right_eye_pan")
AS5048A_COUNT = 360 / 2 ** 14                               # deg
AS5048A_NOISE = 0.06                                        # deg rms, the datasheet's maximum


def _budget(tmp_path, name, edit):
    (tmp_path / name).mkdir()
    return eye_accuracy.budget(edited(tmp_path / name, edit), PEAK)


def _terms(e):
    return {t.name: t for t in e.terms}


def test_todays_spur_gearhead_misses_by_fifty_times(params):
    """FAULHABER 16/7, 43:1: its 2 deg of backlash alone; hysteresis and stiffness not published."""
    e = eye_accuracy.budget(params, PEAK)
    assert e.unknown == ["hysteresis", "wind_up", "home_spread"] and not e.ok
    assert e.known_per_eye_deg / e.per_eye_allowed_deg == pytest.approx(51.9, abs=0.05)


# Harmonic Drive's size-5 strain-wave gear (the RSF-5B supermini actuator's; RSF supermini series manual, sections
# 1-7 and 1-8): one-way accuracy 3 arc-min at each ratio; stiffness K1 up to T1 = 0.075 N m and K2 beyond. Its
# hysteresis loss is in none of the sources reachable: the budget leaves it the figures below (arc-min at the eye).
SIZE_5 = {30: (90, 110, 1.184), 50: (110, 140, 1.248), 100: (150, 180, 0.946)}


def _size_5(ratio, hysteresis=None):
    k1, k2, _ = SIZE_5[ratio]

    def edit(d):
        gear = d["purchased"]["faulhaber-16-7-43"]      # the pans' gearhead entry, edited in this copy only
        gear.update(ratio=ratio, backlash_deg=0, transmission_accuracy_arcmin=3,
                    torsional_stiffness={"T1": 0.075, "K1": k1, "K2": k2})
        if hysteresis is not None:
            gear["hysteresis_loss_arcmin"] = hysteresis
    return edit


@pytest.mark.parametrize("ratio", sorted(SIZE_5))
def test_the_size_5_strain_wave_gear_is_unshown_until_its_hysteresis_is_known(tmp_path, ratio):
    """Every other term known: the budget is not shown met while the hysteresis is unknown, and what it leaves
    the hysteresis is the docs' figure; just under it the gear meets the budget, just over it it does not."""
    e = _budget(tmp_path, "unknown", _size_5(ratio))
    assert e.unknown == ["hysteresis"] and e.per_eye_deg is None and not e.ok
    leaves = (e.per_eye_allowed_deg - e.known_per_eye_deg) * 60
    assert leaves == pytest.approx(SIZE_5[ratio][2], abs=0.0005)
    assert _budget(tmp_path, "under", _size_5(ratio, leaves - 0.01)).ok
    assert not _budget(tmp_path, "over", _size_5(ratio, leaves + 0.01)).ok


def _joint_sensor(readings, coverage=2, drift=None):
    """An AS5048A on each pan's joint, its loop closed on it, zero taken from it; today's 16/7 inside the loop."""
    def edit(d):
        for pan in PANS:
            d["drives"][pan]["joint_encoder"] = "ams-AS5048A"
            d["homing"][pan] = {"method": "absolute_encoder"}
        d["eye_accuracy"]["joint_sensor"] = {"readings": readings, "coverage": coverage}
        if drift is not None:
            d["purchased"]["ams-AS5048A"]["nonlinearity_drift_deg"] = drift
    return edit


def test_a_joint_sensor_takes_the_gear_out_of_the_budget(tmp_path):
    """The gear's backlash, hysteresis and wind-up and the homing stop are inside the loop or gone: what counts
    is the sensor, its noise as 2 sigma of the mean of 64 readings; its non-linearity is calibrated, and how far
    that moves with temperature is not published, so the budget is not shown met."""
    e = _budget(tmp_path, "as5048a", _joint_sensor(64))
    t = _terms(e)
    assert set(t) == {"sensor_count", "sensor_noise", "sensor_linearity", "sensor_drift"}
    assert t["sensor_noise"].deg == pytest.approx(2 * AS5048A_NOISE / math.sqrt(64)) and not t["sensor_noise"].repeatable
    assert t["sensor_count"].deg == 0 and "dithered" in t["sensor_count"].what
    assert t["sensor_linearity"].deg == 0.8 and t["sensor_linearity"].repeatable
    assert e.unknown == ["sensor_drift"] and not e.ok
    assert e.per_eye_allowed_deg - e.known_per_eye_deg == pytest.approx(0.0238, abs=0.00005)


def test_a_joint_sensor_read_once_misses(tmp_path):
    """The broken variant: one reading, its whole count and 2 sigma of its noise: nearly four times the budget,
    whatever the drift."""
    e = _budget(tmp_path, "once", _joint_sensor(1, drift=0))
    t = _terms(e)
    assert t["sensor_count"].deg == pytest.approx(AS5048A_COUNT)
    assert e.per_eye_deg == pytest.approx(AS5048A_COUNT + 2 * AS5048A_NOISE) and not e.ok
    assert e.per_eye_deg / e.per_eye_allowed_deg == pytest.approx(3.66, abs=0.01)
    with pytest.raises(eye_accuracy.EyeAccuracyError, match="does NOT meet it"):
        eye_accuracy.enforce(e)


def test_a_joint_sensor_with_a_known_drift_is_counted_to_the_budget(tmp_path):
    """Were the drift measured, it is counted like the rest: 0.02 deg fits in what the 64 readings leave,
    0.03 does not."""
    assert _budget(tmp_path, "small", _joint_sensor(64, drift=0.02)).ok
    assert not _budget(tmp_path, "large", _joint_sensor(64, drift=0.03)).ok


def test_a_pan_read_at_the_joint_takes_its_zero_from_its_sensor(tmp_path):
    def edit(d):
        _joint_sensor(64)(d)
        d["homing"]["left_eye_pan"] = {"method": "hard_stop", "direction": 1, "stops_deg": [-56.5, 56.5],
                                       "back_off_deg": 28.5}
    with pytest.raises(ParameterError, match=r"homing\.left_eye_pan\.method: a pan read at the joint takes its zero "
                                             r"from its sensor \(ams-AS5048A\): expected 'absolute_encoder'"):
        _budget(tmp_path, "hard_stop", edit)


@pytest.mark.parametrize("edit, message", [
    (lambda d: d["eye_accuracy"]["joint_sensor"].pop("readings"), r"eye_accuracy\.joint_sensor\.readings: missing"),
    (lambda d: d["eye_accuracy"]["joint_sensor"].update(readings=0.5),
     r"eye_accuracy\.joint_sensor\.readings: must be >= 1"),
    (lambda d: d["eye_accuracy"]["joint_sensor"].update(coverage=0),
     r"eye_accuracy\.joint_sensor\.coverage: must be > 0"),
    (lambda d: d["purchased"]["ams-AS5048A"].update(noise_rms_deg="0.06 deg"),
     r"purchased\.ams-AS5048A\.noise_rms_deg: expected a number"),
])
def test_bad_joint_sensor_input_is_named(tmp_path, edit, message):
    def both(d):
        _joint_sensor(64)(d)
        edit(d)
    with pytest.raises(ParameterError, match=message):
        _budget(tmp_path, "bad", both)


TILTS = (-30, -15, 0, 15, 30)          # the eye tilt's range; the pans turn about their own axes, which this keeps


@pytest.fixture(scope="module")
def in_tilt_frame(assembly):
    """Every part at each tilt angle, in the tilt frame (the pan axes stand at (0, +-34) along z, the eye centres at
    z = 0): (link, name, shape, its exact bounds)."""
    posed = {}
    for tilt in TILTS:
        placed = assembly.pose({"eyes_tilt": tilt})
        frame = next(p.world for p in placed if p.part.link == "eyes_tilt_link")
        back = geom.location(np.linalg.inv(frame))
        posed[tilt] = [(p.part.link, p.part.name, shape, *geom.exact_bounds(shape))
                       for p in placed for shape in [p.shape.moved(back)]]
    return posed


def _pan_axes(params):
    return {f"{side}_eye": sign * params.baseline / 2 for side, sign in (("left", 1), ("right", -1))}


def _touching(in_tilt_frame, eye, column):
    """(name, tilt) of every part of another link that the column touches at some tilt (exact distances: the
    face plate is a mesh solid, on which booleans are not reliable)."""
    lo, hi = geom.exact_bounds(column)
    hits = []
    for tilt, shapes in in_tilt_frame.items():
        for link, name, shape, slo, shi in shapes:
            if link in ("eyes_tilt_link", eye):
                continue
            if np.any(slo > hi) or np.any(shi < lo):
                continue
            if geom.distance(column, shape) < 1e-6:
                hits.append((name, tilt))
    return hits


def test_the_room_above_each_eye_for_a_sensor(params, in_tilt_frame):
    """Where a magnet in the cup's top would face a sensor held over the eye: from the cup's top up to the first
    part of another link within the AS5048A board's half-width (11 mm) and the clearance of the pan axis: 6.0 mm,
    the head's top bar at tilt 0."""
    r = params.geometry("eyes").num("cup_radius")
    clear = params.geometry("clearances").num("minimum")
    for eye, y in _pan_axes(params).items():
        assert _touching(in_tilt_frame, eye, geom.cyl("z", 2 * (11 + clear), r, r + 5.95, (0, y))) == [], eye
        assert _touching(in_tilt_frame, eye, geom.cyl("z", 2 * (11 + clear), r, r + 6.05, (0, y))) == \
            [("head_top_bar", 0)], eye


@pytest.mark.parametrize("band, room, limit", [
    ((-40, -24), 25.61, "eyes_tilt_stop_pin_"),         # the 16 mm under the tilt frame's plate
    ((-56, -40), 13.92, "neck_yaw_encoder_bracket"),    # 16 to 32 mm under it (its feet ahead of the yaw boss)
    ((-74, -56), 9.99, "face_plate"),                   # down to the end of today's encoder
])
def test_the_room_around_each_pan_drive(params, in_tilt_frame, band, room, limit):
    """How far from each pan axis the nearest part of another link comes, per height under the tilt frame's
    plate, over the tilt's range: what a drive hung there may fill (less the clearance)."""
    for eye, y in _pan_axes(params).items():
        axis = geom.cyl("z", 0.02, band[0], band[1], (0, y))
        nearest = []
        for tilt, shapes in in_tilt_frame.items():
            for link, name, shape, lo, hi in shapes:
                if link in ("eyes_tilt_link", eye):
                    continue
                if lo[0] > 30 or hi[0] < -30 or lo[1] > y + 30 or hi[1] < y - 30 or lo[2] > band[1] + 30 \
                        or hi[2] < band[0] - 30:
                    continue
                nearest.append((geom.distance(axis, shape), name, tilt))
        found = min(nearest)
        assert found[0] == pytest.approx(room, abs=0.01) and found[1].startswith(limit), (eye, found)


def test_the_room_under_each_pan_drive(params, in_tilt_frame):
    """Under today's encoder (its end 50 mm under the tilt frame's plate), within its 17 mm: 5.3 mm to the face
    plate at +30 deg of tilt."""
    eyes = params.geometry("eyes")
    end = -eyes.num("cup_radius") - eyes.num("gap") - eyes.node("tilt_frame").num("plate_thickness") - 50
    for eye, y in _pan_axes(params).items():
        assert _touching(in_tilt_frame, eye, geom.cyl("z", 17, end - 5.27, end, (0, y))) == [], eye
        assert _touching(in_tilt_frame, eye, geom.cyl("z", 17, end - 5.29, end, (0, y))) == [("face_plate", 30)], eye
