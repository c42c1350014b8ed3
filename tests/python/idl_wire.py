# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The device IDL's wire tables, for tests that walk every request a service dispatches: compiled
from interfaces/idl/ by the code generator (codegen/robogene_codegen), as `make generate` does.

INTERFACES  interface -> (fingerprint, {method: (request path or None, argument types, result types)})
SERVICES    service -> (fingerprint, interface names, protocol request path or None)
STRUCTS     struct -> field names, in wire order
A type is its IDL name, with "[]" when the field holds one value per axis."""
from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
if str(ROOT / "codegen") not in sys.path:
    sys.path.insert(0, str(ROOT / "codegen"))

from robogene_codegen.idl import compile_directory  # noqa: E402

_IDL = compile_directory(ROOT / "interfaces" / "idl", root=ROOT)


def _type(field) -> str:
    return field.type.name + ("[]" if field.per_axis else "")


INTERFACES = {
    iface.name: (iface.fingerprint, {m.name: (tuple(m.wire) if m.wire else None, tuple(map(_type, m.args)),
                                              tuple(map(_type, m.results))) for m in iface.methods})
    for iface in _IDL.interfaces}
SERVICES = {
    s.name: (s.fingerprint, tuple(i.name for i in s.interfaces), tuple(s.protocol.wire) if s.protocol else None)
    for s in _IDL.services}
STRUCTS = {st.name: tuple(f.name for f in st.fields) for st in _IDL.structs}
