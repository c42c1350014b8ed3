# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The built-in Python drivers."""
from .fake_grabber import FakeGrabber
from .test_motor import TestMotor


def _remote_controlboard():
    # Imported when first created: it needs the compiled core, the simulated drivers do not.
    from ..remote_controlboard import RemoteControlboard
    return RemoteControlboard()


def _remote_grabber():
    from ..grabber_network import RemoteGrabber
    return RemoteGrabber()


def add_builtin_drivers(factory) -> None:
    from ..wrappers import add_wrapper_devices
    factory.add("test_motor", "simulated control board: position and velocity moves, encoders", TestMotor)
    factory.add("fake_grabber", "simulated camera: a moving RGB test pattern", FakeGrabber)
    factory.add("remote_controlboard", "a control board served elsewhere (remote, local, server)",
                _remote_controlboard)
    factory.add("remote_grabber", "a camera served elsewhere (remote, local, stream, timeout, server)",
                _remote_grabber)
    add_wrapper_devices(factory)


__all__ = ["FakeGrabber", "TestMotor", "add_builtin_drivers"]
