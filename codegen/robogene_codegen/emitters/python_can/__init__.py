# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Python encoders and decoders of each CAN protocol, the same frames and text form as the C++ ones."""
from __future__ import annotations

from ...can.model import CanField, scalar_range
from ...idl.model import Idl
from ..common import environment, line_comment_header



def py_type(f: CanField) -> str:
    if f.enum:
        return f.enum.name
    if f.flags:
        return f.flags.name
    return {"bool": "bool", "real": "float"}.get(f.kind, "int")


def py_default(f: CanField) -> str:
    if f.enum:
        return f"{f.enum.name}.{f.enum.members[0].name.upper()}"
    if f.flags:
        return f"{f.flags.name}(0)"
    return {"bool": "False", "real": "0.0"}.get(f.kind, "0")


def public_names(p) -> list[str]:
    names = ["PROTOCOL_NAME", "PROTOCOL_FINGERPRINT", "PROTOCOL_MAJOR", "PROTOCOL_MINOR", "BITRATE",
             "HOST_ADDRESS", "FIRST_BOARD_ADDRESS", "LAST_BOARD_ADDRESS", "BROADCAST_ADDRESS", "AXIS_BIT",
             "CodecError", "Frame", "MessageClass", "Command", "BroadcastType", "Message", "MESSAGES",
             "Envelope", "command", "reply", "broadcast", "make_id", "split_id", "encode", "decode",
             "to_text", "from_text"]
    names += [f"{f.name.upper()}_{suffix}" for f in p.id_layout for suffix in ("SHIFT", "MASK")]
    names += [e.name for e in p.enums] + [f.name for f in p.flags] + [m.pascal for m in p.messages]
    return sorted(names)


def emit(idl: Idl) -> dict[str, str]:
    env = environment(__file__)
    env.globals.update(public_names=public_names, py_type=py_type, py_default=py_default, scalar_range=scalar_range, repr=repr)
    out = {}
    modules = []
    for proto in idl.can_protocols:
        header = line_comment_header("#", "BSD-3-Clause", [proto.file])
        out[f"{proto.name}.py"] = env.get_template("protocol.py.j2").render(p=proto, header=header)
        modules.append(proto.name)
    if modules:
        sources = sorted(p.file for p in idl.can_protocols)
        out[f"__init__.py"] = env.get_template("__init__.py.j2").render(
            header=line_comment_header("#", "BSD-3-Clause", sources), modules=modules)
    return out
