# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The built-in Python drivers."""
from .fake_grabber import FakeGrabber
from .test_motor import TestMotor


def add_builtin_drivers(factory) -> None:
    factory.add("test_motor", "simulated control board: position and velocity moves, encoders", TestMotor)
    factory.add("fake_grabber", "simulated camera: a moving RGB test pattern", FakeGrabber)


__all__ = ["FakeGrabber", "TestMotor", "add_builtin_drivers"]
