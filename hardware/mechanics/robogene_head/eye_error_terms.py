# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The angular error terms of one eye-pan drive, per eye at the joint, each split into repeatable (a per-eye
calibration against the cameras removes it) and not repeatable (what the stereo budget counts).

The pans are read from their motor encoders (no joint encoder), so every error between the motor shaft and the eye
cup is the eye's error. A term whose number the maker does not publish is kept as unknown (deg None), never taken as
zero: the budget cannot be shown met while one of its non-repeatable terms is unknown.

Gearhead numbers read from its purchased: entry (each optional, absent = not published):
  backlash_deg                  lost motion at reversal, no load: which flank carries depends on the path taken
  transmission_accuracy_arcmin  one-way angular transmission error over a turn: a function of angle, repeatable
  hysteresis_loss_arcmin        the loop left after loading to +- rated torque: depends on the torque history
  torsional_stiffness           {T1, K1, K2} (N m, N m/rad): the wind-up under a torque, K1 up to T1, K2 beyond
Homing against a hard stop (homing.<joint>.method: hard_stop) adds the stop's offset: at the stall the drive pushes
the lug onto its pin with at most the homing run's own current limit (motor_control.homing.<control joint>
.current_limit, which the firmware holds the motors to while they seek the stop); gearhead and lug wind up under it. That wind-up is the
same at every power-up as far as the stall torque is; its mean is calibrated with the rest, and
eye_accuracy.homing_torque_spread of it (the stall torque's spread) is not repeatable, plus one encoder count.

A pan with an absolute sensor at the joint (drives.<pan>.joint_encoder) is read there instead: its position loop
closes on the sensor, so the gear's backlash, hysteresis and wind-up and the motor encoder's count lie inside the
loop, and the sensor gives the zero at power-up (homing.<pan>.method: absolute_encoder, no stop pressed). What counts
then is the sensor's own error, from its purchased: entry (sensed_terms):
  bits                one count: 360 / 2^bits (none when averaged readings are dithered by the noise)
  noise_rms_deg       the reading's noise (1 sigma): eye_accuracy.joint_sensor.coverage sigma of the mean of its
                      .readings readings is counted
  nonlinearity_deg    the reading's error over the turn at a given magnet placement: a function of angle, calibrated
  nonlinearity_drift_deg  how far that error moves with temperature after the calibration: counted
  accuracy_over_temperature_deg  the maker's bound (+-) on the reading's error over the sensor's whole operating
                      temperature range, relative to its zero (after the maker's or the host's calibration, as the
                      maker states it). Whatever the temperatures at calibration and in use, two readings within +-a
                      differ by at most 2a: without a published drift, twice this bounds it and is counted. Neither
                      published: the drift is unknown."""
from __future__ import annotations

import math
from dataclasses import dataclass

from robogene_head_model import drive_limits
from robogene_head_model.params import HeadParameters, Node, ParameterError

ARCMIN = 1 / 60.0


@dataclass(frozen=True)
class Term:
    name: str
    what: str
    deg: float | None        # per eye at the joint; None: not published, unknown
    repeatable: bool         # True: removed by the per-eye calibration
    source: str


def wind_up(stiffness: Node, torque: float) -> float:
    """rad of wind-up under torque (N m) from the maker's piecewise-linear curve (T1, K1, K2)."""
    t1, k1 = stiffness.num("T1", positive=True), stiffness.num("K1", positive=True)
    if torque <= t1:
        return torque / k1
    if not stiffness.has("K2"):
        raise stiffness.fail("K2", f"missing: {torque:.3g} N m is beyond T1 = {t1:g} N m")
    return t1 / k1 + (torque - t1) / stiffness.num("K2", positive=True)


def stop_compliance(params: HeadParameters) -> float:
    """rad per N m of the eye-pan hard stop: the printed lug on the cup's back, loaded sideways by the pin, as a
    cantilever in bending and shear from where it leaves the cup (at its centre radius) down to the middle of its
    contact with the pin. The pressed steel pin is some 30 times stiffer and is left out."""
    e = params.geometry("eyes")
    s = e.node("hard_stop")
    r, width, depth = s.num("radius", positive=True), s.num("lug_width", positive=True), s.num("lug_depth", positive=True)
    cup = e.num("cup_radius", positive=True)
    plate_top = -cup - e.num("gap", positive=True)               # the tilt frame's plate, in the eye's frame
    pin = params.purchased(s.text("pin"))
    pin_top = plate_top + pin.num("length", positive=True) - s.num("pin_depth", positive=True)
    lug_bottom = plate_top + s.num("lug_gap", positive=True)
    root = -math.sqrt(cup * cup - r * r)
    lever = root - (lug_bottom + pin_top) / 2
    if lever <= 0 or pin_top <= lug_bottom:
        raise ParameterError(f"{params.path}: geometry.eyes.hard_stop: the pin does not reach the lug "
                             f"(pin top {pin_top:.2f}, lug bottom {lug_bottom:.2f} in the eye's frame)")
    acc = params.root.node("eye_accuracy")
    modulus = acc.num("stop_modulus_MPa", positive=True)
    shear = modulus / (2 * (1 + acc.num("stop_poisson", positive=True, maximum=0.5)))
    inertia = depth * width ** 3 / 12                            # bending across the lug's width, the pin's push
    per_newton = lever ** 3 / (3 * modulus * inertia) + lever / (5 / 6 * shear * width * depth)   # mm per N
    return per_newton / (r * r) * 1000                           # a torque T pushes T / r: rad per N m


def homing_current(params: HeadParameters, joint: str) -> float:
    """mA per motor the board holds a pan's motor to while it seeks its stop: the current_limit of the homing run
    of the control joint that drives the pans (motor_control.homing: on the eye board version homes both), never
    more than the run limit (the firmware takes the lower, rg_board.c)."""
    if joint not in drive_limits.PAN_JOINTS:
        raise ParameterError(f"{params.path}: homing.{joint}: the eye budget's homing current is the eye pans' only")
    tuning = params.root.node("motor_control").node("homing")
    runs = [c for c in drive_limits.PAN_CONTROL if tuning.has(c)]
    if not runs:
        raise ParameterError(f"{params.path}: motor_control.homing: no homing run of "
                             f"{' or '.join(drive_limits.PAN_CONTROL)} for {joint}, which homes against a hard stop")
    return min(tuning.node(runs[0]).num("current_limit", positive=True), drive_limits.current_limit(params, joint))


def homing_torque(params: HeadParameters, joint: str) -> float:
    """N m at the joint, at most, that the drive pushes the lug onto its pin with at the stall: the homing run's
    current limit through the gearhead (the homing PWM limit gives less, by the winding's resistance)."""
    drive = params.drive(joint)
    kt = drive_limits.torque_constant(params, drive.text("motor"))
    eta = params.purchased(drive.text("gearhead")).num("efficiency", positive=True, maximum=1.0)
    return kt * homing_current(params, joint) * 1e-3 * drive_limits.reduction(params, joint) * eta


def sensed_terms(params: HeadParameters, joint: str) -> list[Term]:
    """The terms of a pan read at the joint by its absolute sensor (drives.<pan>.joint_encoder)."""
    drive = params.drive(joint)
    key = drive.text("joint_encoder")
    homing = params.root.node("homing").node(joint)
    method = homing.text("method")
    if method != "absolute_encoder":
        raise homing.fail("method", f"a pan read at the joint takes its zero from its sensor ({key}): expected "
                                     f"'absolute_encoder', got {method!r}")
    sensor = params.purchased(key)
    rule = params.root.node("eye_accuracy").node("joint_sensor")
    readings = rule.num("readings", minimum=1)
    coverage = rule.num("coverage", positive=True)

    def published(name: str) -> float | None:
        return sensor.num(name, minimum=0) if sensor.has(name) else None

    noise = published("noise_rms_deg")
    count = 360.0 / 2 ** sensor.num("bits", positive=True)
    # Averaged readings with a noise of half a count or more dither the codes: their mean resolves below a count,
    # and the noise figure, measured on the output codes, carries the quantisation. One reading keeps a whole count.
    dithered = readings > 1 and noise is not None and noise >= count / 2
    unpublished = f"{key}: not published"
    drift, drift_source, drift_what = published("nonlinearity_drift_deg"), f"{key}.nonlinearity_drift_deg", ""
    if drift is None and sensor.has("accuracy_over_temperature_deg"):
        drift = 2 * sensor.num("accuracy_over_temperature_deg", minimum=0)
        drift_source = f"2 x {key}.accuracy_over_temperature_deg"
        drift_what = " (at most twice the maker's accuracy over temperature)"
    elif drift is None:
        drift_source = unpublished
    return [
        Term("sensor_count", "one count of the joint sensor" + (" (dithered by its noise: in sensor_noise)"
                                                                 if dithered else ""),
             0.0 if dithered else count, False, f"{key}.bits"),
        Term("sensor_noise", f"the joint sensor's noise, {coverage:g} sigma of the mean of {readings:g} readings",
             None if noise is None else coverage * noise / math.sqrt(readings), False,
             f"{key}.noise_rms_deg; eye_accuracy.joint_sensor" if noise is not None else unpublished),
        Term("sensor_linearity", "the joint sensor's non-linearity over the turn", published("nonlinearity_deg"), True,
             f"{key}.nonlinearity_deg" if sensor.has("nonlinearity_deg") else unpublished),
        Term("sensor_drift", "its non-linearity's change with temperature since the calibration" + drift_what,
             drift, False, drift_source),
    ]


def terms(params: HeadParameters, joint: str, dynamic_Nm: float) -> list[Term]:
    """The terms of one pan; dynamic_Nm: the peak torque the gearhead passes to the eye (drive sizing's load)."""
    drive = params.drive(joint)
    if drive.has("joint_encoder"):
        return sensed_terms(params, joint)
    gear_key, enc_key = drive.text("gearhead"), drive.text("encoder")
    gear = params.purchased(gear_key)
    belt = drive_limits.belt_ratio(params, joint)
    count = 360.0 / (4 * params.purchased(enc_key).num("lines", positive=True) * drive_limits.reduction(params, joint))

    def arcmin(key: str) -> float | None:
        return gear.num(key, minimum=0) * ARCMIN / belt if gear.has(key) else None

    stiff = gear.node("torsional_stiffness") if gear.has("torsional_stiffness") else None
    dyn = math.degrees(wind_up(stiff, dynamic_Nm)) / belt if stiff else None
    unpublished = f"{gear_key}: not published"
    out = [
        Term("backlash", "gearhead backlash (lost motion at reversal)",
             gear.num("backlash_deg", minimum=0) / belt if gear.has("backlash_deg") else None, False,
             f"{gear_key}.backlash_deg" if gear.has("backlash_deg") else unpublished),
        Term("transmission", "gearhead transmission error over the range", arcmin("transmission_accuracy_arcmin"), True,
             f"{gear_key}.transmission_accuracy_arcmin" if gear.has("transmission_accuracy_arcmin") else unpublished),
        Term("hysteresis", "gearhead hysteresis loss", arcmin("hysteresis_loss_arcmin"), False,
             f"{gear_key}.hysteresis_loss_arcmin" if gear.has("hysteresis_loss_arcmin") else unpublished),
        Term("wind_up", f"gearhead wind-up under the eye's peak torque ({dynamic_Nm * 1000:.2f} mN m)", dyn, False,
             f"{gear_key}.torsional_stiffness" if stiff else f"{gear_key}: stiffness not published"),
        Term("quantisation", "one count of the motor encoder", count, False, f"{enc_key}.lines x reduction"),
    ]
    homing = params.root.node("homing").node(joint)
    method = homing.text("method")
    if method != "hard_stop":
        raise homing.fail("method", f"the eye budget counts hard_stop homing only, got {method!r}")
    t_home = homing_torque(params, joint)
    spread = params.root.node("eye_accuracy").num("homing_torque_spread", minimum=0, maximum=1)
    lug = math.degrees(t_home * stop_compliance(params))
    gear_home = math.degrees(wind_up(stiff, t_home)) / belt if stiff else None
    at = f"{t_home:.3f} N m at the stall ({homing_current(params, joint):g} mA)"
    out += [
        Term("stop_offset", f"the lug's bending on its pin, {at}", lug, True,
             "homing current limit x kt x reduction x efficiency; lug cantilever (eye_accuracy.stop_*)"),
        Term("stop_spread", f"its spread ({spread:.0%}) and one count read at the stall", spread * lug + count, False,
             "eye_accuracy.homing_torque_spread"),
        Term("home_wind_up", f"gearhead wind-up, {at}", gear_home, True,
             f"{gear_key}.torsional_stiffness" if stiff else f"{gear_key}: stiffness not published"),
        Term("home_spread", f"its spread ({spread:.0%})", None if gear_home is None else spread * gear_home, False,
             "eye_accuracy.homing_torque_spread"),
    ]
    return out
