# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""YARP 3's PID offset, enable, disable and reset requests over RPC against test_motor opened from
Python: the replies in the shapes of RPCMessagesParser::handlePidMsg, and the model's behaviour
through the generated client, bytes and the generated server dispatch, both bound from C++
(robogene.dev.ControlboardClient, ControlboardServer). The C++ test is
drivers/fake/test/framework/pid_switches_rpc_test.cpp."""
import math

import pytest

from robogene import Bottle
from robogene.dev import (ControlboardClient, ControlboardServer, ControlMode, DeviceDriver, ISimulationClock, Pid,
                          PidType, PolyDriver, Property)


@pytest.fixture
def remote():
    """A three-axis test_motor on a manual clock, its server, and a client through bytes."""
    device = PolyDriver(Property.from_dict({"device": "test_motor", "axes": 3, "clock": "manual"}))
    assert device.is_valid(), device.last_error
    server = ControlboardServer(device.view(DeviceDriver))
    client = ControlboardClient(lambda request: Bottle.from_bytes(
        server.respond(Bottle.from_bytes(request.to_bytes())).to_bytes()))
    yield device.view(ISimulationClock), server, client
    device.close()


def test_replies_have_yarps_shapes(remote):
    _, server, _ = remote
    ask = lambda text: server.respond(Bottle.from_text(text)).to_text()  # noqa: E731
    assert ask("[get] [pid] [ena] [pos] 0") == "[is] [pid] 1 [ok]"
    # isPidEnabled's bool is an int32, as handlePidMsg's addInt32; no stamp.
    assert server.respond(Bottle.from_text("[get] [pid] [ena] [vel] 2")).to_bytes().hex() == (
        "0001000004000000" "0900000069730000" "0900000070696400" "0100000001000000" "090000006f6b0000")
    assert ask("[set] [pid] [off] [pos] 1 2.5") == "[ok]"
    assert ask("[get] [pid] [pid] [pos] 1") == "[is] [pid] (0.0 0.0 0.0 0.0 0.0 2.5 0.0 0.0 0.0 0.0) [ok]"
    assert ask("[set] [pid] [dis] [trq] 0") == "[ok]"
    assert ask("[get] [pid] [ena] [trq] 0") == "[is] [pid] 0 [ok]"
    assert ask("[set] [pid] [ena] [trq] 0") == "[ok]"
    assert ask("[set] [pid] [res] [pos] 0") == "[ok]"
    assert ask("[set] [pid] [off] [pos] 1") == "[fail]"  # no value
    assert ask("[set] [pid] [ena] [xyz] 1") == "[fail]"  # no such PID type
    assert ask("[get] [pid] [ena] [cur] 1") == "[fail]"  # no current loop
    assert ask("[set] [pid] [dis] [pos] 3") == "[fail]"  # no axis 3


def test_offset_is_the_gains_offset_for_every_controller(remote):
    _, _, client = remote
    gains = Pid(6000, 500, 5, 1333, 1333, 0, 8, 0.5, -0.5, 1)
    assert client.setPid(PidType.VELOCITY, 2, gains)
    assert client.setPidOffset(PidType.VELOCITY, 2, -7.0)
    expected = Pid(6000, 500, 5, 1333, 1333, -7.0, 8, 0.5, -0.5, 1)
    assert client.getPid(PidType.VELOCITY, 2) == expected
    assert client.setPidOffset(PidType.CURRENT, 0, 3.0)  # the current loop's gains are kept too
    assert client.getPid(PidType.CURRENT, 0).offset == 3.0
    assert client.setPidOffset(PidType.VELOCITY, 2, math.nan) is False
    assert client.setPidOffset(PidType.VELOCITY, 3, 1.0) is False
    assert client.getPid(PidType.VELOCITY, 2) == expected


def test_a_disabled_loop_frees_its_axis_and_cannot_run_until_enabled(remote):
    device, _, client = remote
    for t in (PidType.POSITION, PidType.VELOCITY, PidType.TORQUE):
        assert client.isPidEnabled(t, 1) is True
    assert client.isPidEnabled(PidType.CURRENT, 1) is None  # no current loop
    assert client.enablePid(PidType.CURRENT, 1) is False
    assert client.disablePid(PidType.CURRENT, 1) is False

    # Axis 1 moving to 40: disabling its position loop frees it where it is.
    assert client.positionMove(1, 40.0) and device.advance(1.0)
    there = client.getEncoder(1)
    assert there > 1.0
    assert client.disablePid(PidType.POSITION, 1)
    assert client.isPidEnabled(PidType.POSITION, 1) is False
    assert client.getControlMode(1) == ControlMode.IDLE
    assert device.advance(1.0)
    assert client.getEncoder(1) == there

    # Nothing may run it again: single and all-axes moves, the mode, a PID query of the loop.
    assert client.positionMove(1, 10.0) is False
    assert client.relativeMove(1, 1.0) is False
    assert client.positionMoveAll([5.0, 5.0, 5.0]) is False  # axis 1 in it: none moves
    assert client.setControlMode(1, ControlMode.POSITION) is False
    assert client.setControlModes([ControlMode.IDLE, ControlMode.POSITION, ControlMode.IDLE]) is False
    assert client.getPidReference(PidType.POSITION, 1) is None
    assert client.getControlModes() == [ControlMode.POSITION, ControlMode.IDLE, ControlMode.POSITION]
    assert client.getTargetPosition(0) == 0.0
    # Other loops and other axes still work.
    assert client.velocityMove(1, 2.0) and client.getControlMode(1) == ControlMode.VELOCITY
    assert client.positionMove(0, 3.0)

    assert client.enablePid(PidType.POSITION, 1)
    assert client.isPidEnabled(PidType.POSITION, 1) is True
    assert client.getControlMode(1) == ControlMode.VELOCITY  # enabling does not take the axis over
    assert client.positionMove(1, 10.0) and client.getControlMode(1) == ControlMode.POSITION

    # A loop the axis does not run is only switched off; the torque loop the same way.
    assert client.disablePid(PidType.VELOCITY, 1)
    assert client.getControlMode(1) == ControlMode.POSITION
    assert client.velocityMove(1, 1.0) is False
    assert client.setRefTorque(2, 0.5)
    assert client.disablePid(PidType.TORQUE, 2)
    assert client.getControlMode(2) == ControlMode.IDLE
    assert client.setRefTorque(2, 0.5) is False
    assert client.setControlMode(2, ControlMode.TORQUE) is False


def test_reset_makes_what_the_running_loop_measures_its_reference(remote):
    device, _, client = remote
    # Position: mid-move, the target becomes the present position, held from standstill.
    assert client.positionMove(0, 40.0) and device.advance(1.0)
    assert client.getPidError(PidType.POSITION, 0) > 1.0
    assert client.resetPid(PidType.POSITION, 0)
    there = client.getEncoder(0)
    assert client.getTargetPosition(0) == there and client.getEncoderSpeed(0) == 0.0
    assert client.getPidError(PidType.POSITION, 0) == 0.0
    assert device.advance(1.0)
    assert client.getEncoder(0) == there and client.checkMotionDone(0) is True

    # Velocity: mid-ramp, the present speed becomes the command and the ramp ends there.
    assert client.velocityMove(1, 10.0) and device.advance(0.1)  # 5 deg/s of the 10, at 50 deg/s^2
    assert client.resetPid(PidType.VELOCITY, 1)
    speed = client.getEncoderSpeed(1)
    assert speed == pytest.approx(5.0, abs=1e-9)
    assert client.getPidReference(PidType.VELOCITY, 1) == speed and client.getRefVelocity(1) == speed
    assert device.advance(1.0)
    assert client.getEncoderSpeed(1) == speed

    # A loop the axis does not run has nothing to reset; the torque loop follows its reference.
    assert client.resetPid(PidType.TORQUE, 1)
    assert client.getEncoderSpeed(1) == speed
    assert client.resetPid(PidType.CURRENT, 1) is False
