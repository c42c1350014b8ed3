# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Canonical forms and fingerprints.

The canonical form keeps what changes the meaning or the bytes on the wire (names, types, units,
vocab paths, echo positions, reply stamps, defaults, enum values, struct layouts) and drops documentation, so
rewording a doc string keeps a fingerprint while any wire-visible change alters it. A fingerprint
is the first 16 hex digits of the SHA-256 of the canonical JSON.
"""
from __future__ import annotations

import hashlib
import json

from .model import EnumType, Field, Interface, Method, Service, StructType


def _field(f: Field) -> dict:
    out = {"name": f.name, "type": f.type.name, "per_axis": f.per_axis}
    if f.unit:
        out["unit"] = f.unit
    if f.has_default:
        out["default"] = f.default
    return out


def method_shape(m: Method) -> dict:
    out = {"name": m.name, "cpp_name": m.cpp_name, "form": m.form,
           "wire": list(m.wire) if m.wire else None, "echo": m.echo,
           "args": [_field(a) for a in m.args], "results": [_field(r) for r in m.results]}
    if not m.stamp:  # only when set, so that the fingerprints of stamped interfaces stay as they were
        out["stamp"] = False
    if m.reply_head is not None:
        out["reply"] = list(m.reply_head)
    return out


def _enum(e: EnumType) -> dict:
    return {"name": e.name, "wire": e.wire, "members": [[m.name, m.value] for m in e.members]}


def _struct(s: StructType) -> dict:
    return {"name": s.name, "fields": [_field(f) for f in s.fields]}


def _digest(canonical: dict) -> tuple[str, str]:
    text = json.dumps(canonical, sort_keys=True, separators=(",", ":"), ensure_ascii=True)
    return text, hashlib.sha256(text.encode("ascii")).hexdigest()[:16]


def interface_canonical(iface: Interface) -> dict:
    return {"interface": iface.name, "version": iface.version,
            "methods": [method_shape(m) for m in iface.methods],
            "enums": [_enum(e) for e in iface.enums], "structs": [_struct(s) for s in iface.structs]}


def assign_interface(iface: Interface) -> None:
    iface.canonical, iface.fingerprint = _digest(interface_canonical(iface))


def assign_service(service: Service) -> None:
    canonical = {
        **({"replies": service.replies} if service.replies != "stamped" else {}),
        **({"command_reply": list(service.command_reply)} if service.command_reply else {}),
        "service": service.name, "version": service.version, "rpc_port": service.rpc_port,
        "interfaces": [[i.name, i.fingerprint] for i in service.interfaces],
        "protocol": None if service.protocol is None else {
            "wire": list(service.protocol.wire), "reply": service.protocol.reply,
            "version": list(service.protocol.version)},
        "introspection": list(service.introspection) if service.introspection else None,
        "streams": [{"name": s.name, "port": s.port, "source": f"{s.interface}.{s.method.name}",
                     "period": s.period} for s in service.streams],
        "command": None if service.command is None else {
            "port": service.command.port, "prefix": list(service.command.prefix),
            **({"aliases": [[list(h), f"{m.interface}.{m.name}"] for h, m in service.command.aliases]}
               if service.command.aliases else {})},
    }
    service.canonical, service.fingerprint = _digest(canonical)
