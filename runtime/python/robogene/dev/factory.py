# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""DriverFactory: devices by symbolic name (paper section 3.2)."""
from __future__ import annotations

import threading
from typing import Callable, Dict, List, Optional, Tuple

from .device_driver import DeviceDriver

Creator = Callable[[], DeviceDriver]


class DriverFactory:
    _instance: Optional["DriverFactory"] = None
    _instance_lock = threading.Lock()

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._drivers: Dict[str, Tuple[str, Creator]] = {}

    @classmethod
    def instance(cls) -> "DriverFactory":
        with cls._instance_lock:
            if cls._instance is None:
                factory = cls()
                from .drivers import add_builtin_drivers
                add_builtin_drivers(factory)
                cls._instance = factory
            return cls._instance

    def add(self, name: str, description: str, create: Creator) -> None:
        if not name or not callable(create):
            raise ValueError("DriverFactory: a driver needs a name and a creator")
        with self._lock:
            if name in self._drivers:
                raise ValueError(f"DriverFactory: driver {name!r} is already known")
            self._drivers[name] = (description, create)

    def has(self, name: str) -> bool:
        with self._lock:
            return name in self._drivers

    def names(self) -> List[str]:
        with self._lock:
            return sorted(self._drivers)

    def create(self, name: str) -> DeviceDriver:
        with self._lock:
            entry = self._drivers.get(name)
            known = ", ".join(sorted(self._drivers))
        if entry is None:
            raise LookupError(f"unknown device {name!r} (known devices: {known})")
        device = entry[1]()
        if not isinstance(device, DeviceDriver):
            raise TypeError(f"device {name!r}: its creator returned {type(device).__name__}, not a DeviceDriver")
        return device
