# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Devices (paper section 3): interfaces generated from the IDL, Property, DriverFactory,
PolyDriver, and the built-in test_motor."""
from .device_driver import DeviceDriver, ISimulationClock
from .factory import DriverFactory
from .generated import *  # noqa: F401,F403
from .generated import __all__ as _generated
from .image import ImageRgb
from .poly_driver import PolyDriver
from .property import ConfigError, Property

__all__ = ["ConfigError", "DeviceDriver", "DriverFactory", "ISimulationClock", "ImageRgb",
           "PolyDriver", "Property"] + list(_generated)
