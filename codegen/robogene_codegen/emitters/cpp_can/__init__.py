# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""C++ encoders and decoders of each CAN protocol: one struct per frame layout, encode/decode to
robogene::can::Frame, and a text form shared with the Python codec."""
from __future__ import annotations

from ...can.model import SCALARS, CanField, CanProtocol, scalar_range
from ...idl.model import Idl
from ..common import environment, line_comment_header, snake

OUT_DIR = "drivers/can/generated"


def field_type(f: CanField) -> str:
    if f.enum:
        return f.enum.name
    if f.kind == "real":
        return "double"
    return SCALARS[f.scalar][2]


def field_default(f: CanField) -> str:
    if f.enum:
        return f"{f.enum.name}::{f.enum.members[0].name}"
    if f.kind == "bool":
        return "false"
    return "0.0" if f.kind == "real" else "0"


def literal(x: float) -> str:
    text = repr(float(x))
    return text if ("e" in text or "." in text) else text + ".0"


def int_literal(v: int) -> str:
    # The most negative int32 has no literal of its own in C++.
    return f"({v + 1} - 1)" if v == -(1 << 31) else (f"{v}LL" if abs(v) >= 1 << 31 else str(v))


def cpp_scalar(name: str) -> str:
    return "std::uint8_t" if name == "bool" else SCALARS[name][2]


def commands_of(cls) -> list[tuple]:
    """(code, request, reply or None) of each command of a class, by code."""
    by_code: dict[int, list] = {}
    for m in cls.messages:
        if m.kind != "broadcast":
            by_code.setdefault(m.code, [None, None])[0 if m.kind == "request" else 1] = m
    return [(code, pair[0], pair[1]) for code, pair in sorted(by_code.items())]


def emit(idl: Idl) -> dict[str, str]:
    env = environment(__file__)
    env.filters["snake"] = snake
    env.globals.update(cpp_scalar=cpp_scalar, commands_of=commands_of, field_type=field_type, field_default=field_default, literal=literal,
                       scalar_range=scalar_range, int_literal=int_literal)
    out = {}
    for proto in idl.can_protocols:
        header = line_comment_header("//", "BSD-3-Clause", [proto.file])
        ctx = {"p": proto, "header": header, "include": f"{proto.name}.hpp"}
        out[f"{OUT_DIR}/{proto.name}.hpp"] = env.get_template("protocol.hpp.j2").render(ctx)
        out[f"{OUT_DIR}/{proto.name}.cpp"] = env.get_template("protocol.cpp.j2").render(ctx)
    return out
