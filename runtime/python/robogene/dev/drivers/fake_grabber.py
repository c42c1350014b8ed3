# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""fake_grabber in Python: the same simulated camera and test pattern as the C++ driver (see
drivers/fake/fake_grabber/fake_grabber.hpp for the pattern and the configuration keys)."""
from __future__ import annotations

import math
import threading
import time
from typing import Optional

from ..device_driver import DeviceDriver, ISimulationClock, SimClock
from ..generated import CameraFeature, FeatureMode, IFrameGrabberControls, IFrameGrabberImage
from ..image import ImageRgb
from ..property import Property

_SUPPORTED = (CameraFeature.BRIGHTNESS, CameraFeature.EXPOSURE, CameraFeature.SHUTTER, CameraFeature.GAIN)


def draw(width: int, height: int, n: int) -> ImageRgb:
    """Frame n of the pattern, before brightness and gain. Built a row at a time (red and blue
    only change along a row, green only down a column), fast enough for 640x480 at 30 Hz."""
    image = ImageRgb()
    image.resize(width, height)
    red = bytes((x + 2 * n) % 256 for x in range(width))
    rows = []  # the two rows of the checkerboard, by the parity of (y // 16 + n // 8)
    for parity in (0, 1):
        row = bytearray(width * 3)
        row[0::3] = red
        row[2::3] = bytes(200 if (x // 16 + parity) % 2 else 40 for x in range(width))
        rows.append(row)
    stride = width * 3
    p = image.pixels
    for y in range(height):
        row = rows[(y // 16 + n // 8) % 2]
        row[1::3] = bytes(((y + n) % 256,)) * width
        p[y * stride:(y + 1) * stride] = row
    return image


class _Feature:
    def __init__(self) -> None:
        self.value, self.active, self.mode = 0.5, True, FeatureMode.MANUAL


class FakeGrabber(DeviceDriver, IFrameGrabberImage, IFrameGrabberControls, ISimulationClock):
    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._clock = SimClock()
        self._open = False
        self._width, self._height, self._rate = 320, 240, 30.0
        self._last_frame = -1
        self._features = {}

    def open(self, config: Property) -> bool:
        with self._lock:
            self._width = config.get_int("width", 320, 1, 4096)
            self._height = config.get_int("height", 240, 1, 4096)
            self._rate = config.get_float("framerate", 30.0, 0.1, 1000.0)
            self._clock.configure(config)
            self._features = {f: _Feature() for f in _SUPPORTED}
            self._last_frame = -1
            self._open = True
            return True

    def close(self) -> bool:
        with self._lock:
            self._open = False
            return True

    def now(self) -> float:
        with self._lock:
            return self._clock.now()

    def advance(self, seconds: float) -> bool:
        with self._lock:
            return self._open and self._clock.advance(seconds)

    def _effective(self, f: CameraFeature) -> float:
        feat = self._features.get(f)
        if feat is None or not feat.active or feat.mode == FeatureMode.AUTOMATIC:
            return 0.5
        return feat.value

    def getImage(self) -> Optional[ImageRgb]:
        with self._lock:
            if not self._open:
                return None
            n = math.floor(self._clock.now() * self._rate)
            if not self._clock.manual and n <= self._last_frame:
                wait = (self._last_frame + 1) / self._rate - self._clock.now()
            else:
                wait = 0.0
        if wait > 0:
            time.sleep(wait)  # without the lock, so the controls stay usable
        with self._lock:
            if not self._open:
                return None
            if not self._clock.manual:
                n = max(self._last_frame + 1, math.floor(self._clock.now() * self._rate))
            self._last_frame = n
            image = draw(self._width, self._height, n)
            gain = 2.0 * self._effective(CameraFeature.GAIN)
            offset = (self._effective(CameraFeature.BRIGHTNESS) - 0.5) * 255.0
        if gain != 1.0 or offset != 0.0:
            table = bytes(min(255, max(0, _round(b * gain + offset))) for b in range(256))
            image.pixels = bytearray(image.pixels.translate(table))
        return image

    def height(self) -> Optional[int]:
        with self._lock:
            return self._height if self._open else None

    def width(self) -> Optional[int]:
        with self._lock:
            return self._width if self._open else None

    def _feature(self, f) -> Optional[_Feature]:
        return self._features.get(f) if self._open else None

    def hasFeature(self, feature: CameraFeature) -> Optional[bool]:
        with self._lock:
            return feature in _SUPPORTED if self._open else None

    def setFeature(self, feature: CameraFeature, value: float) -> bool:
        with self._lock:
            feat = self._feature(feature)
            if feat is None or isinstance(value, bool) or not isinstance(value, (int, float)) \
                    or not 0.0 <= value <= 1.0:
                return False
            feat.value = float(value)
            return True

    def getFeature(self, feature: CameraFeature) -> Optional[float]:
        with self._lock:
            feat = self._feature(feature)
            return feat.value if feat else None

    def setActive(self, feature: CameraFeature, onoff: bool = True) -> bool:
        with self._lock:
            feat = self._feature(feature)
            if feat is None:
                return False
            feat.active = bool(onoff)
            return True

    def getActive(self, feature: CameraFeature) -> Optional[bool]:
        with self._lock:
            feat = self._feature(feature)
            return feat.active if feat else None

    def setMode(self, feature: CameraFeature, mode: FeatureMode = FeatureMode.MANUAL) -> bool:
        with self._lock:
            feat = self._feature(feature)
            if feat is None or mode not in (FeatureMode.MANUAL, FeatureMode.AUTOMATIC):
                return False
            feat.mode = FeatureMode(mode)
            return True

    def getMode(self, feature: CameraFeature) -> Optional[FeatureMode]:
        with self._lock:
            feat = self._feature(feature)
            return feat.mode if feat else None


def _round(x: float) -> int:
    """C's lround (halves away from zero), so both languages draw the same bytes."""
    return int(math.floor(x + 0.5)) if x >= 0 else -int(math.floor(-x + 0.5))
