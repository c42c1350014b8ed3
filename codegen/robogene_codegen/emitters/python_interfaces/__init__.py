# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Python abstract classes with type hints, the shared enums and structs, and the wire tables."""
from __future__ import annotations

from ...idl.model import Field, Idl, Method, TypeRef
from ..common import (all_sources, described, environment, help_lines, identifier,
                      line_comment_header, param_name, vocab_int, wire_vocabs)


_SCALARS = {"joint": "int", "int32": "int", "float64": "float", "bool": "bool", "string": "str",
            "vocab": "int", "image_rgb": "ImageRgb"}


def py_type(t: TypeRef) -> str:
    return t.name if t.kind != "builtin" else _SCALARS[t.name]


def hint(f: Field, sequence: str = "Sequence") -> str:
    return f"{sequence}[{py_type(f.type)}]" if f.per_axis else py_type(f.type)


def py_default(f: Field) -> str:
    if f.type.enum:
        return f"{f.type.name}.{f.default.upper()}"
    if f.type.name == "vocab":
        return str(vocab_int(f.default))
    if f.type.name == "float64":
        return repr(float(f.default))
    return repr(f.default)


def params(m: Method) -> str:
    out = ["self"]
    for a in m.args:
        p = f"{param_name(a)}: {hint(a)}"
        if a.has_default:
            p += f" = {py_default(a)}"
        out.append(p)
    return ", ".join(out)


def returns(m: Method) -> str:
    if not m.results:
        return "bool"
    types = [hint(r, "List") for r in m.results]
    return f"Optional[{types[0]}]" if len(types) == 1 else f"Optional[Tuple[{', '.join(types)}]]"


def client_methods(service) -> list:
    """One method per Python name: interfaces sharing a method (getAxes...) share its client."""
    seen: dict = {}
    for iface in service.interfaces:
        for m in iface.methods:
            seen.setdefault(m.name, m)
    return list(seen.values())


def type_names(fields) -> str:
    return "(" + "".join(f'"{f.type.name}{"[]" if f.per_axis else ""}", ' for f in fields) + ")"


def class_name(service) -> str:
    return "".join(p.capitalize() for p in service.name.split("_")) + "Client"


def emit(idl: Idl) -> dict[str, str]:
    env = environment(__file__)
    helpers = dict(client_methods=client_methods, type_names=type_names, class_name=class_name,
                   py_type=py_type, params=params, returns=returns, described=described,
                   vocab_int=vocab_int, identifier=identifier, param_name=param_name, hint=hint,
                   help_lines=help_lines)
    header = line_comment_header("#", "BSD-3-Clause", all_sources(idl))
    out = {}
    for name in ("__init__.py", "types.py", "interfaces.py", "wire.py", "clients.py"):
        out[name] = env.get_template(f"{name}.j2").render(
            header=header, idl=idl, vocabs=wire_vocabs(idl), **helpers)
    return out
