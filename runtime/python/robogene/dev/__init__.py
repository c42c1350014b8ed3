# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Devices: interfaces generated from the IDL, and the image type they share."""
from .image import ImageRgb

__all__ = ["ImageRgb"]
