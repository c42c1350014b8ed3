# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""ImageRgb: packed 8-bit RGB pixels, rows top to bottom without padding."""
from __future__ import annotations

from dataclasses import dataclass, field


@dataclass
class ImageRgb:
    width: int = 0
    height: int = 0
    pixels: bytearray = field(default_factory=bytearray)  # width * height * 3 bytes

    def resize(self, width: int, height: int) -> None:
        if width < 0 or height < 0:
            raise ValueError(f"image size {width}x{height} is negative")
        self.width, self.height = width, height
        self.pixels = bytearray(width * height * 3)

    def pixel(self, x: int, y: int) -> tuple[int, int, int]:
        if not (0 <= x < self.width and 0 <= y < self.height):
            raise IndexError(f"pixel ({x}, {y}) is outside {self.width}x{self.height}")
        i = (y * self.width + x) * 3
        return self.pixels[i], self.pixels[i + 1], self.pixels[i + 2]
