# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""C++ encoders and decoders of each CAN protocol: one struct per frame layout, encode/decode to
robogene::can::Frame, and a text form shared with the Python codec."""
from __future__ import annotations

from ...can.model import SCALARS, CanField, CanProtocol, scalar_range
from ...idl.model import Idl
from ..common import environment, line_comment_header, snake



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


def _range_args(f: CanField) -> str:
    lo, hi = scalar_range(f.scalar)
    return f"{int_literal(lo)}, {int_literal(hi)}"


def _put(m, f: CanField) -> str:
    at = f"f, {f.byte}, {f.size}, "
    if f.kind == "enum":
        return f'  put({at}wire_of(m.{f.name}, "{m.name}", "{f.name}"));'
    if f.kind == "bool":
        return f"  put({at}m.{f.name} ? 1 : 0);"
    if f.kind == "real":
        return (f"  put({at}to_raw(m.{f.name}, {literal(f.scale)}, {literal(f.offset)}, {_range_args(f)}, "
                f'"{m.name}", "{f.name}", "{f.unit or ""}"));')
    return f"  put({at}static_cast<std::int64_t>(m.{f.name}));"


def _take(m, f: CanField) -> str:
    raw = f"get(f, {f.byte}, {f.size}, {'true' if f.signed else 'false'})"
    if f.kind == "enum":
        return f'  m.{f.name} = {snake(f.enum.name)}_from_wire({raw}, "{m.name}", "{f.name}");'
    if f.kind == "bool":
        return f'  m.{f.name} = bool_from_wire({raw}, "{m.name}", "{f.name}");'
    if f.kind == "real":
        return f"  m.{f.name} = from_raw({raw}, {literal(f.scale)}, {literal(f.offset)});"
    return f"  m.{f.name} = static_cast<{field_type(f)}>({raw});"


def _text(f: CanField) -> str:
    value = {"enum": f"std::string(to_string(m.{f.name}))",
             "bool": f'std::string(m.{f.name} ? "true" : "false")',
             "real": f"real_text(m.{f.name})",
             "flags": f"flags_text(m.{f.name}, {f.size})"}.get(f.kind, f"std::to_string(m.{f.name})")
    return f'  s += " {f.name}=" + {value};'


def _parse(m, f: CanField) -> str:
    if f.kind == "enum":
        return f'  m.{f.name} = {snake(f.enum.name)}_from_text(t.word("{f.name}"), "{m.name}", "{f.name}");'
    if f.kind == "bool":
        return f'  m.{f.name} = t.boolean("{f.name}");'
    if f.kind == "real":
        return f'  m.{f.name} = t.real("{f.name}");'
    return f'  m.{f.name} = static_cast<{field_type(f)}>(t.integer("{f.name}", {_range_args(f)}));'


def message_functions(m) -> str:
    """put_fields, take_fields, text_fields and parse_fields of one message (built here rather than
    in the template: Jinja compiles templates on every run, and this keeps that cheap)."""
    def body(lines: list[str], names: tuple) -> str:
        return "\n".join(lines) if lines else "\n".join(f"  (void){n};" for n in names)
    return "\n".join([
        f"void put_fields(Frame& f, const {m.pascal}& m) {{", body([_put(m, f) for f in m.fields], ("f", "m")), "}", "",
        f"void take_fields(const Frame& f, {m.pascal}& m) {{", body([_take(m, f) for f in m.fields], ("f", "m")), "}", "",
        f"void text_fields(std::string& s, const {m.pascal}& m) {{", body([_text(f) for f in m.fields], ("s", "m")), "}", "",
        f"void parse_fields(TextFields& t, {m.pascal}& m) {{", body([_parse(m, f) for f in m.fields], ("t", "m")), "}"])


def emit(idl: Idl) -> dict[str, str]:
    env = environment(__file__)
    env.filters["snake"] = snake
    env.globals.update(cpp_scalar=cpp_scalar, commands_of=commands_of, message_functions=message_functions, field_type=field_type, field_default=field_default, literal=literal,
                       scalar_range=scalar_range, int_literal=int_literal)
    out = {}
    for proto in idl.can_protocols:
        header = line_comment_header("//", "BSD-3-Clause", [proto.file])
        ctx = {"p": proto, "header": header, "include": f"{proto.name}.hpp"}
        out[f"{proto.name}.hpp"] = env.get_template("protocol.hpp.j2").render(ctx)
        out[f"{proto.name}.cpp"] = env.get_template("protocol.cpp.j2").render(ctx)
    return out
