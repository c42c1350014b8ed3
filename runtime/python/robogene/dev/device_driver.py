# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""DeviceDriver: what every device implements (paper section 3.1), and the simulation clock of
the fake devices."""
from __future__ import annotations

import abc
import math
import time

from .property import ConfigError, Property


class DeviceDriver(abc.ABC):
    @abc.abstractmethod
    def open(self, config: Property) -> bool:
        """Start the device; False (or ConfigError naming the bad key) when it cannot."""

    @abc.abstractmethod
    def close(self) -> bool:
        """Release what open() took."""


class ISimulationClock(abc.ABC):
    """The time of a simulated device: with `clock manual` it only moves on advance()."""

    @abc.abstractmethod
    def now(self) -> float: ...

    @abc.abstractmethod
    def advance(self, seconds: float) -> bool: ...


class SimClock:
    def __init__(self) -> None:
        self.manual = False
        self._now = 0.0
        self._start = time.monotonic()

    def configure(self, config: Property) -> None:
        kind = config.get_string("clock", "wall")
        if kind not in ("wall", "manual"):
            raise ConfigError(f"{config.origin('clock')}: key 'clock': expected wall or manual, got {kind!r}")
        self.manual = kind == "manual"
        self._now = 0.0
        self._start = time.monotonic()

    def now(self) -> float:
        return self._now if self.manual else time.monotonic() - self._start

    def advance(self, seconds: float) -> bool:
        if not self.manual or not isinstance(seconds, (int, float)) or not math.isfinite(seconds) or seconds < 0:
            return False
        self._now += seconds
        return True
