# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The Python side of devices: Property, PolyDriver and test_motor, paper section 3.3 included,
through the bound C++ device layer (robogene.dev is robogene._core's; needs `make python`)."""
import math
import time

import pytest

from robogene.dev import (ConfigError, ControlMode, DriverFactory, IControlMode, IEncoders,  # noqa: E402
                          IFrameGrabberImage, IPidControl, IPositionControl, ISimulationClock, ITorqueControl,
                          IVelocityControl, PidType, PolyDriver, Property)


def profile(t, v, a, distance):
    """Rest-to-rest position after t seconds: a trapezoid, or a triangle for short moves."""
    peak = min(v, math.sqrt(a * distance))
    ramp = peak / a
    total = distance / peak + ramp
    if t <= 0:
        return 0.0
    if t < ramp:
        return 0.5 * a * t * t
    if t < total - ramp:
        return 0.5 * a * ramp * ramp + peak * (t - ramp)
    if t < total:
        return distance - 0.5 * a * (total - t) ** 2
    return distance


TOL = 0.01


def manual_motor(axes=4):
    config = Property.from_dict({"device": "test_motor", "axes": axes, "clock": "manual"})
    device = PolyDriver(config)
    assert device.is_valid(), device.last_error
    return device, device.view(ISimulationClock)


def test_paper_section_3_3_as_written():
    device = PolyDriver()
    device.open("test_motor")

    ipos = device.view(IPositionControl)
    ivel = device.view(IVelocityControl)
    assert ipos is not None and ivel is not None

    start = time.monotonic()
    ipos.setRefAcceleration(0, 100)
    ipos.setRefSpeed(0, 5)
    ipos.positionMove(0, 40)

    ivel.setRefAcceleration(1, 100)
    ivel.velocityMove(1, 5)

    time.sleep(0.3)
    encs = device.view(IEncoders).getEncoders()
    elapsed = time.monotonic() - start
    assert len(encs) == 4
    assert profile(0.3, 5, 100, 40) - TOL <= encs[0] <= profile(elapsed, 5, 100, 40) + TOL
    assert profile(0.3, 5, 100, 1e9) - TOL <= encs[1] <= profile(elapsed, 5, 100, 1e9) + TOL
    assert encs[2:] == [0.0, 0.0]
    assert ipos.checkMotionDone(0) is False


def test_position_move_follows_the_profile_in_simulated_time():
    device, clock = manual_motor()
    ipos, enc = device.view(IPositionControl), device.view(IEncoders)
    ipos.setRefAcceleration(0, 100)
    ipos.setRefSpeed(0, 5)
    ipos.positionMove(0, 40)
    peak = 0.0
    for step in range(1, 806):  # 8.05 s in 10 ms steps
        assert clock.advance(0.01)
        assert enc.getEncoder(0) == pytest.approx(profile(step * 0.01, 5, 100, 40), abs=TOL)
        peak = max(peak, abs(enc.getEncoderSpeed(0)))
    assert peak == pytest.approx(5.0, abs=1e-9)
    assert clock.advance(1.0)
    assert enc.getEncoder(0) == 40.0 and ipos.checkMotionDone(0) is True


def test_velocity_move_stop_and_modes():
    device, clock = manual_motor()
    ivel, enc = device.view(IVelocityControl), device.view(IEncoders)
    assert ivel.setRefAcceleration(1, 100) and ivel.velocityMove(1, 5)
    assert clock.advance(10.0)
    assert enc.getEncoder(1) == pytest.approx(50.0 - 25.0 / 200, abs=TOL)
    assert device.view(IPositionControl).getTargetPosition(1) == 0.0
    assert device.view(IVelocityControl).getRefVelocity(1) == 5.0
    assert device.view(IControlMode).getControlMode(1) == ControlMode.VELOCITY
    before = enc.getEncoder(1)
    assert ivel.stop(1)
    assert clock.advance(1.0)
    assert enc.getEncoder(1) == pytest.approx(before + 25.0 / 200, abs=TOL)
    assert enc.getEncoderSpeed(1) == 0.0


def test_bad_requests_are_refused_and_change_nothing():
    device, clock = manual_motor(2)
    ipos = device.view(IPositionControl)
    assert ipos.positionMove(2, 1.0) is False
    with pytest.raises(TypeError):  # an axis is an int, never a bool (True is not axis 1)
        ipos.positionMove(True, 1.0)
    assert ipos.positionMove(0, float("nan")) is False
    assert ipos.setRefSpeed(0, 0.0) is False
    assert ipos.positionMoveAll([1.0, 2.0, 3.0]) is False
    assert ipos.setRefSpeeds([5.0, -1.0]) is False
    assert ipos.getRefSpeed(0) == 10.0
    assert device.view(IControlMode).setControlMode(0, ControlMode.CURRENT) is False  # not simulated
    assert clock.advance(-1) is False
    assert device.view(IEncoders).getEncoder(5) is None
    assert device.view(IEncoders).getEncoders() == [0.0, 0.0]


def test_torque_mode_is_a_damped_body_and_modes_hand_over():
    """The C++ twin is TestMotor.TorqueModeIsADampedBodyAndModesHandOver."""
    device = PolyDriver(Property.from_dict({"device": "test_motor", "axes": 2, "clock": "manual", "inertia": 0.02,
                                            "damping": 0.1, "max_torque": 2}))
    clock, modes, torque = device.view(ISimulationClock), device.view(IControlMode), device.view(ITorqueControl)
    enc, pos = device.view(IEncoders), device.view(IPositionControl)
    tau, deg = 0.02 / 0.1, 180.0 / math.pi
    assert modes.setControlMode(0, ControlMode.TORQUE) and torque.getRefTorque(0) == 0.0
    assert torque.setRefTorque(0, 1.0) and clock.advance(0.3)
    w_end = 1.0 / 0.1 * deg
    assert enc.getEncoderSpeed(0) == pytest.approx(w_end * (1 - math.exp(-0.3 / tau)), abs=1e-9)
    assert enc.getEncoder(0) == pytest.approx(w_end * (0.3 - tau * (1 - math.exp(-0.3 / tau))), abs=1e-9)
    assert pos.stop(0) and clock.advance(20 * tau) and abs(enc.getEncoderSpeed(0)) < 1e-6
    assert torque.setRefTorque(0, -2.0) and clock.advance(0.5)
    assert modes.setControlMode(0, ControlMode.POSITION) and clock.advance(60.0)
    assert enc.getEncoder(0) == pos.getTargetPosition(0) and torque.getTorque(0) == 0.0
    assert torque.setRefTorque(1, 2.5) is False
    bad = PolyDriver()
    assert not bad.open(Property.from_dict({"device": "test_motor", "damping": 0}))
    assert "damping" in bad.last_error


def test_view_of_an_unimplemented_interface_is_none():
    device = PolyDriver("test_motor")
    assert device.view(IFrameGrabberImage) is None
    assert device.view(IEncoders).getAxes() == 4
    device.close()
    assert device.view(IEncoders) is None


def test_failures_say_what_and_where():
    device = PolyDriver()
    assert not device.open("dragonfly")
    assert device.last_error.startswith("device 'dragonfly': unknown device 'dragonfly' (known devices: ")
    assert not device.open(Property.from_ini("axes 2\n", "motor.ini"))
    assert device.last_error == "motor.ini: no 'device' key naming the driver to open"
    assert not device.open(Property.from_ini("device test_motor\naxes 100\n", "motor.ini"))
    assert device.last_error == "device 'test_motor': motor.ini:2: key 'axes': 100 is outside [1, 64]"
    assert "test_motor" in DriverFactory.instance().names()


def test_property_from_ini_command_line_and_dict():
    p = Property.from_ini('# motor\ndevice test_motor // c\naxes 2\nname "/m # x"\nlim 0.0 90.5 (1 2)\n'
                          "flag\n[GENERAL]\nJoints 4\n", "motor.ini")
    assert p.get_string("device", "") == "test_motor"
    assert p.get_int("axes", 0, 1, 64) == 2
    assert p.get_string("name", "") == "/m # x"
    assert p.find("lim") == [0.0, 90.5, [1, 2]]
    assert p.get_bool("flag", False) is True
    assert p.find_group("GENERAL").get_int("Joints", 0, 0, 9) == 4
    assert p.origin("axes") == "motor.ini:3"
    c = Property.from_command_line(["--device", "test_motor", "--axes", "2", "--single_port",
                                    "--GENERAL::Joints", "4", "--pos", "1", "2.5"])
    assert c.get_int("axes", 0, 0, 9) == 2 and c.get_bool("single_port", False)
    assert c.find_group("GENERAL").get_int("Joints", 0, 0, 9) == 4
    assert c.find("pos") == [1, 2.5]
    assert c.origin("axes") == "command line argument 3"
    n = Property.from_ini("hex 0x1F\noct 010\nnotoct 09\nneg -5\nf 1e3\n", "n.ini")
    # 09 reads as YARP 3 reads it (a number by its characters, then strtol in base 0): 0.
    assert [n.find(k) for k in ("hex", "oct", "notoct", "neg", "f")] == [31, 8, 0, -5, 1000.0]


def test_property_from_a_bottle_as_the_cpp_one_reads_it():
    from robogene import Bottle  # the compiled core
    b = Bottle.from_text('(device test_motor) (axes 2) (pos 1 2.5) (name "/m x") (mode [vel]) (flag) '
                         '(lim (0.0 90.5)) (GENERAL (Joints 4) (AxisName "neck" "eyes"))')
    p = Property.from_bottle(b)
    assert p.get_string("device", "") == "test_motor" and p.get_int("axes", 0, 1, 64) == 2
    assert p.find("pos") == [1, 2.5] and p.get_string("name", "") == "/m x"
    assert p.find("mode") == "vel" and p.get_bool("flag", False) is True
    assert p.find("lim") == [0.0, 90.5]  # a list value, not a group: its first item is no key
    general = p.find_group("GENERAL")
    assert general.get_int("Joints", 0, 0, 9) == 4 and general.find("AxisName") == ["neck", "eyes"]
    assert p.origin("axes") == "bottle item 1" and general.origin("Joints") == "bottle item 7 item 0"
    with pytest.raises(ConfigError, match=r"^bottle item 1: expected \(key value\.\.\.\), got 7$"):
        Property.from_bottle(Bottle.from_text("(axes 2) 7"))
    device = PolyDriver()
    assert not device.open(Property.from_bottle(Bottle.from_text("(device test_motor) (axes 100)"), "rpc"))
    assert device.last_error == "device 'test_motor': rpc item 1: key 'axes': 100 is outside [1, 64]"
    assert device.open(Property.from_bottle(b)) and device.view(IEncoders).getAxes() == 2


@pytest.mark.parametrize("text,message", [
    ("axes 2\n  speed (1 2\n", "m.ini:2:9: '(' has no matching ')'"),
    ("axes 2\n[broken\n", "m.ini:2:1: a group header is [name], got '[broken'"),
    ("axes 2\naxes 3\n", "m.ini:2:1: key 'axes' is already set at m.ini:1"),
])
def test_ini_errors_name_file_line_and_column(text, message):
    with pytest.raises(ConfigError) as info:
        Property.from_ini(text, "m.ini")
    assert str(info.value) == message


def test_typed_reads_name_the_origin():
    p = Property.from_ini("axes two\nspeed 1e9\nflag maybe\n", "m.ini")
    with pytest.raises(ConfigError, match=r"^m\.ini:1: key 'axes': expected an integer, got two$"):
        p.get_int("axes", 0, 1, 64)
    with pytest.raises(ConfigError, match=r"^m\.ini:2: key 'speed': 1000000000\.0 is outside"):
        p.get_float("speed", 0, 0, 100)
    with pytest.raises(ConfigError, match=r"^m\.ini:3: key 'flag': expected true or false"):
        p.get_bool("flag", False)
    with pytest.raises(ConfigError, match=r"^m\.ini: missing key 'nope'$"):
        p.require("nope")


def grabber(extra=None):
    config = {"device": "fake_grabber", "width": 64, "height": 48, "framerate": 25, "clock": "manual"}
    config.update(extra or {})
    device = PolyDriver(Property.from_dict(config))
    assert device.is_valid(), device.last_error
    return device


def test_fake_grabber_pattern_moves_between_frames():
    device = grabber()
    img = device.view(IFrameGrabberImage)
    assert (img.width(), img.height()) == (64, 48)
    a = img.getImage()
    assert device.view(ISimulationClock).advance(1 / 25)
    b = img.getImage()
    assert [a.pixel(x, y) for x, y in ((0, 0), (17, 3), (40, 20))] == [(0, 0, 40), (17, 3, 200), (40, 20, 200)]
    for y in range(47):
        for x in range(62):
            assert b.pixel(x, y)[0] == a.pixel(x + 2, y)[0]
            assert b.pixel(x, y)[1] == a.pixel(x, y + 1)[1]


def test_fake_grabber_brightness_gain_and_controls():
    from robogene.dev import CameraFeature, FeatureMode, IFrameGrabberControls
    device = grabber()
    img, ctl = device.view(IFrameGrabberImage), device.view(IFrameGrabberControls)
    plain = img.getImage()
    assert ctl.setFeature(CameraFeature.BRIGHTNESS, 0.75)
    bright = img.getImage()
    assert bright.pixels == bytes(min(255, p + 64) for p in plain.pixels)
    assert ctl.setFeature(CameraFeature.BRIGHTNESS, 0.5) and ctl.setFeature(CameraFeature.GAIN, 0.25)
    assert img.getImage().pixels == bytes(int(p * 0.5 + 0.5) for p in plain.pixels)
    assert ctl.hasFeature(CameraFeature.FOCUS) is False
    assert ctl.setFeature(CameraFeature.FOCUS, 0.5) is False
    assert ctl.setFeature(CameraFeature.SHUTTER, 1.5) is False
    assert ctl.setMode(CameraFeature.SHUTTER) and ctl.getMode(CameraFeature.SHUTTER) == FeatureMode.MANUAL
    assert ctl.setMode(CameraFeature.SHUTTER, FeatureMode.UNKNOWN) is False


def test_fake_grabber_wall_clock_rate():
    device = PolyDriver(Property.from_dict({"device": "fake_grabber", "width": 8, "height": 8, "framerate": 50}))
    img = device.view(IFrameGrabberImage)
    img.getImage()
    start = time.monotonic()
    for _ in range(5):
        assert img.getImage() is not None
    assert time.monotonic() - start >= 4 / 50


AXIS_MAIN = r"""
#include <cstdio>
#include "axis_motion.hpp"
using robogene::dev::AxisMotion;
int main() {
  AxisMotion a;
  a.set_dynamics(0.02, 0.1);  // as test_motor opens with `inertia 0.02 damping 0.1`
  a.set_ref_speed(5); a.set_ref_acceleration(100); a.move_to(40);
  for (int i = 0; i < 300; ++i) { a.step(0.01); std::printf("%.17g %.17g\n", a.position(), a.velocity()); }
  a.stop();
  a.move_at(-3);
  for (int i = 0; i < 100; ++i) { a.step(0.013); std::printf("%.17g %.17g\n", a.position(), a.velocity()); }
  a.stop();
  for (int i = 0; i < 50; ++i) { a.step(0.01); std::printf("%.17g %.17g\n", a.position(), a.velocity()); }
  // Torque control, its release, and the hand-over to position control.
  a.push(0.0); a.push(1.5);
  for (int i = 0; i < 100; ++i) { a.step(0.007); std::printf("%.17g %.17g %.17g\n", a.position(), a.velocity(), a.torque()); }
  a.stop();
  for (int i = 0; i < 50; ++i) { a.step(0.01); std::printf("%.17g %.17g %.17g\n", a.position(), a.velocity(), a.torque()); }
  a.push(-0.5);
  for (int i = 0; i < 50; ++i) { a.step(0.01); std::printf("%.17g %.17g %.17g\n", a.position(), a.velocity(), a.torque()); }
  a.move_to(a.position()); a.stop();
  for (int i = 0; i < 400; ++i) { a.step(0.01); std::printf("%.17g %.17g %.17g\n", a.position(), a.velocity(), a.torque()); }
  // Reset loops: a velocity ramp cut short, then a position move held where it is.
  a.move_at(4);
  for (int i = 0; i < 3; ++i) { a.step(0.01); std::printf("%.17g %.17g %.17g\n", a.position(), a.velocity(), a.torque()); }
  a.keep_velocity();
  std::printf("%.17g %.17g %.17g\n", a.position(), a.velocity(), a.torque());
  for (int i = 0; i < 20; ++i) { a.step(0.01); std::printf("%.17g %.17g %.17g\n", a.position(), a.velocity(), a.torque()); }
  a.move_to(a.position() + 10);
  for (int i = 0; i < 20; ++i) { a.step(0.01); std::printf("%.17g %.17g %.17g\n", a.position(), a.velocity(), a.torque()); }
  a.hold();
  for (int i = 0; i < 20; ++i) { a.step(0.01); std::printf("%.17g %.17g %.17g\n", a.position(), a.velocity(), a.torque()); }
  return 0;
}
"""


def test_test_motor_from_python_follows_the_cpp_axis_model(tmp_path):
    """test_motor, opened from Python and driven through its interfaces only (position, velocity,
    torque, the mode hand-over, PID resets), moves as its C++ axis model (axis_motion.cpp, compiled
    on its own) does on the same commands. The simulated clock adds up the steps, so a step it
    hands the model may differ from the program's in the last bit: equal to 1e-9."""
    import subprocess
    from pathlib import Path

    drivers = Path(__file__).resolve().parents[2] / "drivers" / "fake" / "test_motor"
    (tmp_path / "main.cpp").write_text(AXIS_MAIN)
    exe = tmp_path / "axis"
    cc = subprocess.run(["g++", "-std=c++17", "-O2", "-ffp-contract=off", "-I", str(drivers),
                         str(tmp_path / "main.cpp"), str(drivers / "axis_motion.cpp"), "-o", str(exe)],
                        capture_output=True, text=True)
    assert cc.returncode == 0, cc.stderr
    cpp = [tuple(float(x) for x in line.split()) for line in
           subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout.splitlines()]

    device = PolyDriver(Property.from_dict({"device": "test_motor", "axes": 1, "clock": "manual",
                                            "inertia": 0.02, "damping": 0.1, "max_torque": 5}))
    assert device.is_valid(), device.last_error
    clock, enc, pos = device.view(ISimulationClock), device.view(IEncoders), device.view(IPositionControl)
    vel, trq, modes = device.view(IVelocityControl), device.view(ITorqueControl), device.view(IControlMode)
    pids = device.view(IPidControl)
    py = []

    def run(dt: float, n: int, with_torque: bool) -> None:
        for _ in range(n):
            assert clock.advance(dt)
            py.append((enc.getEncoder(0), enc.getEncoderSpeed(0)) + ((trq.getTorque(0),) if with_torque else ()))

    assert pos.setRefSpeed(0, 5.0) and pos.setRefAcceleration(0, 100.0) and pos.positionMove(0, 40.0)
    run(0.01, 300, False)
    assert pos.stop(0) and vel.velocityMove(0, -3.0)
    run(0.013, 100, False)
    assert vel.stop(0)
    run(0.01, 50, False)
    assert modes.setControlMode(0, ControlMode.TORQUE) and trq.setRefTorque(0, 1.5)
    run(0.007, 100, True)
    assert pos.stop(0)
    run(0.01, 50, True)
    assert trq.setRefTorque(0, -0.5)
    run(0.01, 50, True)
    assert modes.setControlMode(0, ControlMode.POSITION)  # brake, and hold where the axis comes to rest
    run(0.01, 400, True)
    assert vel.velocityMove(0, 4.0)
    run(0.01, 3, True)
    assert pids.resetPid(PidType.VELOCITY, 0)  # the speed stays as the ramp left it
    py.append((enc.getEncoder(0), enc.getEncoderSpeed(0), trq.getTorque(0)))
    run(0.01, 20, True)
    assert pos.positionMove(0, enc.getEncoder(0) + 10.0)
    run(0.01, 20, True)
    assert pids.resetPid(PidType.POSITION, 0)  # held where it is
    run(0.01, 20, True)

    assert len(py) == len(cpp)
    for step, (ours, model) in enumerate(zip(py, cpp)):
        assert ours == pytest.approx(model, abs=1e-9), f"step {step}"
    cut = cpp[-61]
    assert 0.0 < cut[1] < 4.0 and all(p[1] == pytest.approx(cut[1], abs=1e-9) for p in py[-60:-40])
