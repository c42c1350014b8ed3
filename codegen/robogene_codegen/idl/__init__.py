# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The IDL front end: YAML with source marks, JSON Schema, semantic checks, fingerprints."""
from .errors import IdlError, IdlErrors, Mark
from .compiler import compile_directory, compile_files
from .model import Idl

__all__ = ["IdlError", "IdlErrors", "Mark", "Idl", "compile_directory", "compile_files"]
