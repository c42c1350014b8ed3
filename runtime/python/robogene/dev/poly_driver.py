# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""PolyDriver: owns one device made by the factory and hands out its interfaces (paper 3.2).

    device = PolyDriver()
    device.open("test_motor")
    ipos = device.view(IPositionControl)   # None when the device does not implement it
"""
from __future__ import annotations

from typing import Optional, Type, TypeVar, Union

from .device_driver import DeviceDriver
from .factory import DriverFactory
from .property import ConfigError, Property

T = TypeVar("T")


class PolyDriver:
    def __init__(self, config: Union[str, Property, None] = None):
        self._device: Optional[DeviceDriver] = None
        self.last_error = ""
        if config is not None:
            self.open(config)

    def open(self, config: Union[str, Property]) -> bool:
        """Opens the driver named `config`, or named by the `device` key of a Property."""
        self.close()
        self.last_error = ""
        if isinstance(config, str):
            name = config
            config = Property(f"device {name!r} defaults")
            config.put("device", name, "PolyDriver.open argument")
        try:
            name = config.get_string("device", "")
        except ConfigError as exc:
            self.last_error = str(exc)
            return False
        if not name:
            self.last_error = f"{config.source()}: no 'device' key naming the driver to open"
            return False
        try:
            device = DriverFactory.instance().create(name)
            if not device.open(config):
                self.last_error = f"device {name!r} failed to open"
                return False
        except (ConfigError, LookupError, TypeError) as exc:
            self.last_error = f"device {name!r}: {exc}" if not str(exc).startswith("unknown device") else str(exc)
            return False
        self._device = device
        return True

    def close(self) -> bool:
        if self._device is None:
            return True
        ok = self._device.close()
        self._device = None
        return ok

    def is_valid(self) -> bool:
        return self._device is not None

    def view(self, interface: Type[T]) -> Optional[T]:
        """The device as `interface` if it implements it (Python's dynamic_cast), else None."""
        return self._device if isinstance(self._device, interface) else None

    def __enter__(self) -> "PolyDriver":
        return self

    def __exit__(self, *exc) -> None:
        self.close()
