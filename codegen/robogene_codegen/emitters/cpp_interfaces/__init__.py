# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""C++ abstract interfaces, the shared enums and structs, and the vocab constants."""
from __future__ import annotations

from ...idl.model import Field, Idl, Method, TypeRef
from ..common import (all_sources, described, environment, identifier, interface_sources,
                      line_comment_header, param_name, vocab_int, wire_vocabs)


_SCALARS = {"joint": "int", "int32": "std::int32_t", "float64": "double", "bool": "bool",
            "string": "std::string", "vocab": "robogene::vocab_t", "image_rgb": "ImageRgb"}
_BY_VALUE = {"joint", "int32", "float64", "bool", "vocab"}


def cpp_type(t: TypeRef) -> str:
    return t.name if t.kind != "builtin" else _SCALARS[t.name]


def element_type(f: Field) -> str:
    return cpp_type(f.type)


def value_type(f: Field) -> str:
    return f"std::vector<{cpp_type(f.type)}>" if f.per_axis else cpp_type(f.type)


def in_param(f: Field) -> str:
    by_value = not f.per_axis and (f.type.kind == "enum" or f.type.name in _BY_VALUE)
    return f"{value_type(f)} {param_name(f)}" if by_value else f"const {value_type(f)}& {param_name(f)}"


def out_param(f: Field) -> str:
    return f"{value_type(f)}& {param_name(f)}"


def cpp_default(f: Field) -> str:
    v = f.default
    if f.type.enum:
        return f"{f.type.name}::{v}"
    if isinstance(v, bool):
        return "true" if v else "false"
    if f.type.name == "float64":
        return repr(float(v))
    if f.type.name == "vocab":
        return f'robogene::vocab("{v}")'
    if f.type.name == "string":
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    return str(v)


def signature(m: Method) -> str:
    params = []
    for a in m.args:
        p = in_param(a)
        if a.has_default:
            p += f" = {cpp_default(a)}"
        params.append(p)
    params += [out_param(r) for r in m.results]
    return f"bool {m.cpp_name}({', '.join(params)})"


def unit_note(f: Field) -> str:
    unit = f" [{f.unit}]" if f.unit else ""
    return f"{param_name(f)}{unit}"


def header_name(name: str) -> str:
    return f"{name.lower()}.hpp"


def emit(idl: Idl) -> dict[str, str]:
    env = environment(__file__)
    helpers = dict(cpp_type=cpp_type, signature=signature, unit_note=unit_note, described=described,
                   vocab_int=vocab_int, identifier=identifier, header_name=header_name)
    out = {}
    sources = [f for f in all_sources(idl) if any(t.mark.file == f for t in idl.enums + idl.structs)]
    out[f"types.hpp"] = env.get_template("types.hpp.j2").render(
        header=line_comment_header("//", "BSD-3-Clause", sources), idl=idl, **helpers)
    out[f"vocabs.hpp"] = env.get_template("vocabs.hpp.j2").render(
        header=line_comment_header("//", "BSD-3-Clause", all_sources(idl)), vocabs=wire_vocabs(idl),
        **helpers)
    for iface in idl.interfaces:
        out[header_name(iface.name)] = env.get_template("interface.hpp.j2").render(
            header=line_comment_header("//", "BSD-3-Clause", interface_sources(iface, idl)),
            iface=iface, needs_image=any(r.type.name == "image_rgb" for m in iface.methods
                                         for r in m.results), **helpers)
    out[f"interfaces.hpp"] = env.get_template("interfaces.hpp.j2").render(
        header=line_comment_header("//", "BSD-3-Clause", all_sources(idl)), idl=idl, **helpers)
    return out
