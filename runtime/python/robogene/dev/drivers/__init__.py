# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The built-in Python drivers."""
from .test_motor import TestMotor


def add_builtin_drivers(factory) -> None:
    factory.add("test_motor", "simulated control board: position and velocity moves, encoders", TestMotor)


__all__ = ["TestMotor", "add_builtin_drivers"]
