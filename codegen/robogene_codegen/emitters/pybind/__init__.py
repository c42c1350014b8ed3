# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""pybind11 bindings of the generated C++ interfaces, enums and structs for robogene._core.

Each interface is bound twice over: Python calls a C++ device through it (out-parameters become
the return value, None when the device says no), and a Python class derived from it implements
it for C++ (the trampoline: a C++ call reaches the Python method under the GIL and its return
value fills the out-parameters). The typed stub of these bindings is robogene/_core.pyi, made
from the compiled module by runtime/python/gen_stub.py like the rest of the module's."""
from __future__ import annotations

from ...idl.model import Field, Idl, Method
from ..common import all_sources, described, environment, line_comment_header, param_name, vocab_int
from ..cpp_interfaces import cpp_default, cpp_type, in_param, value_type


def override_signature(m: Method) -> str:
    """The C++ virtual the trampoline overrides (the same as cpp_interfaces declares)."""
    params = [in_param(a) for a in m.args] + [f"{value_type(r)}& {param_name(r)}" for r in m.results]
    return f"bool {m.cpp_name}({', '.join(params)})"


def bound_param(f: Field) -> str:
    """A parameter of a bound method: as the C++ interface takes it, but an axis index is a Joint,
    which refuses a bool (dev_support.hpp)."""
    if f.type.name == "joint" and not f.per_axis:
        return f"Joint {param_name(f)}"
    return in_param(f)


def result_type(m: Method) -> str:
    """What the bound method returns to Python: bool for a command, else the value or None."""
    if not m.results:
        return "bool"
    if len(m.results) == 1:
        return f"std::optional<{value_type(m.results[0])}>"
    return f"std::optional<std::tuple<{', '.join(value_type(r) for r in m.results)}>>"


def arg_names(m: Method) -> str:
    return ", ".join(param_name(a) for a in m.args)


def call_args(m: Method) -> str:
    return ", ".join([param_name(a) for a in m.args] + [param_name(r) for r in m.results])


def py_default(f: Field) -> str:
    """The C++ expression of an argument's default; a string is spelled std::string so py::arg_v keeps its type."""
    text = cpp_default(f)
    return f"std::string({text})" if f.type.name == "string" and not f.type.enum else text


def py_args(m: Method) -> str:
    """The py::arg list of a bound method, defaults included."""
    out = []
    for a in m.args:
        text = f'py::arg("{param_name(a)}")'
        if a.has_default and a.type.enum:
            # Spelled for the docstring (and so the stub) as Python writes the member.
            text = (f'py::arg_v("{param_name(a)}", {py_default(a)}, '
                    f'"{a.type.name}.{a.default.upper()}")')
        elif a.has_default:
            text += f" = {py_default(a)}"
        out.append(text)
    return "".join(f", {a}" for a in out)


def cpp_string(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", " ") + '"'


def emit(idl: Idl) -> dict[str, str]:
    env = environment(__file__)
    helpers = dict(cpp_type=cpp_type, value_type=value_type, in_param=in_param, bound_param=bound_param,
                   override_signature=override_signature, result_type=result_type,
                   arg_names=arg_names, call_args=call_args, py_args=py_args, param_name=param_name,
                   described=described, cpp_string=cpp_string, vocab_int=vocab_int)
    header = line_comment_header("//", "BSD-3-Clause", all_sources(idl))
    needs_image = any(f.type.name == "image_rgb" for i in idl.interfaces for m in i.methods
                      for f in m.args + m.results)
    return {"bind_interfaces.cpp": env.get_template("bind_interfaces.cpp.j2").render(
        header=header, idl=idl, needs_image=needs_image, **helpers)}
