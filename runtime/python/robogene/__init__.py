# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Robogene: YARP-3-compatible bottles, ports and devices, bound from the C++ core.

    >>> import robogene
    >>> robogene.Bottle.from_text('[set] [pos] 1 30.3').to_bytes().hex()[:16]
    '0001000004000000'
"""
from ._core import (  # noqa: F401  (re-exported API)
    Bottle,
    Error,
    NetworkError,
    ParseError,
    Value,
    __version__,
    vocab,
    vocab_to_string,
)

__all__ = [
    "Bottle",
    "Error",
    "NetworkError",
    "ParseError",
    "Value",
    "__version__",
    "vocab",
    "vocab_to_string",
]
