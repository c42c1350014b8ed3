# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Errors that name the file, line and column of the fault, like a compiler's."""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True, order=True)
class Mark:
    """A place in an IDL file; line and column are 1-based."""

    file: str
    line: int
    column: int

    def __str__(self) -> str:
        return f"{self.file}:{self.line}:{self.column}"


@dataclass(frozen=True)
class IdlError:
    mark: Mark
    message: str

    def __str__(self) -> str:
        return f"{self.mark}: error: {self.message}"


class IdlErrors(Exception):
    """Every error found in one compilation, sorted by place."""

    def __init__(self, errors: list[IdlError]):
        self.errors = sorted(errors, key=lambda e: (e.mark, e.message))
        super().__init__("\n".join(str(e) for e in self.errors))
