# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""robogene.decode_joint_data, the C++ decoder of jointData through the binding: it reads what
the C++ encoder (robogene.dev.encode_joint_data, what stateExt:o publishes) writes of a device,
fields flagged [fail] are None, and a malformed message raises robogene.Error naming the item and
the field."""
from __future__ import annotations

import pytest

from robogene import Bottle, Error, decode_joint_data
from robogene.dev import (ControlMode, DeviceDriver, IEncoders, ISimulationClock, ITorqueControl, IVelocityControl,
                          PolyDriver, Property, encode_joint_data)


def test_reads_what_the_python_encoder_writes():
    with PolyDriver(Property.from_dict({"device": "test_motor", "axes": 2, "clock": "manual"})) as motor:
        enc = motor.view(IEncoders)
        assert enc.setEncoders([10.0, -20.0])
        assert motor.view(IVelocityControl).velocityMove(1, 5.0)
        assert motor.view(ISimulationClock).advance(0.05)
        data = decode_joint_data(encode_joint_data(motor.view(DeviceDriver)))
        assert data.axes == 2
        assert data.position == enc.getEncoders()
        assert data.velocity == enc.getEncoderSpeeds()
        assert data.acceleration == enc.getEncoderAccelerations()
        assert data.velocity[1] == pytest.approx(2.5)
        assert data.torque == motor.view(ITorqueControl).getTorques()
        assert data.control_mode == [int(ControlMode.POSITION), int(ControlMode.VELOCITY)]
        # What test_motor has no interface for is flagged [fail]: None here.
        assert data.motor_position is None and data.pwm is None and data.current is None
        assert data.interaction_mode is None


def test_a_malformed_message_names_the_item_and_the_field():
    fields = ["(1.0 2.0) [ok]"] * 9 + ["(0 0) [ok]"] * 2
    with pytest.raises(Error, match=r"^jointData has 2 items, expected 22"):
        decode_joint_data(Bottle.from_text("(1.0 2.0) [ok]"))
    bad = list(fields)
    bad[1] = "(1.0 2.0) [maybe]"
    with pytest.raises(Error, match=r"^jointData item 3 \(jointVelocity\): expected the flag \[ok\] or \[fail\], "
                                    r"got \[mayb\]$"):
        decode_joint_data(Bottle.from_text(" ".join(bad)))
    bad = list(fields)
    bad[6] = "(1.0) [ok]"
    with pytest.raises(Error, match=r"^jointData item 12 \(torque\): has 1 values, but jointPosition has 2$"):
        decode_joint_data(Bottle.from_text(" ".join(bad)))
    good = decode_joint_data(Bottle.from_text(" ".join(fields)))
    assert good.position == [1.0, 2.0] and good.control_mode == [0, 0]


class OnlyDriver(DeviceDriver):
    """A device with no interface at all."""

    def open(self, config):
        return True

    def close(self):
        return True


def test_a_device_without_encoders_has_no_joint_data():
    assert encode_joint_data(OnlyDriver()) is None
