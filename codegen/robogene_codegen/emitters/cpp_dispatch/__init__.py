# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""C++ server dispatch: for each service, a class that turns a request bottle into calls on a
device's interfaces and a reply bottle of YARP 3's shape; plus the wire codec of enums/structs."""
from __future__ import annotations

from dataclasses import dataclass

from ...idl.model import Field, Idl, Interface, Method, Service
import json

from ..common import (all_sources, environment, help_lines, identifier, line_comment_header,
                      param_name, vocab_text)
from ..cpp_interfaces import cpp_type, header_name, in_param, out_param, value_type


def cpp_signature(m: Method, qualified: str = "") -> str:
    """The method's C++ signature without default arguments (for overrides and definitions)."""
    params = [in_param(a) for a in m.args] + [out_param(r) for r in m.results]
    return f"bool {qualified}{m.cpp_name}({', '.join(params)})"



@dataclass
class Route:
    wire: tuple
    echo: int
    method: Method                  # the shape (all candidates share it)
    candidates: list                # [(Interface, Method)] in the service's order

    @property
    def handler(self) -> str:
        return "h_" + "_".join(identifier(v) for v in self.wire)


def routes(service: Service) -> list[Route]:
    found: dict[tuple, Route] = {}
    for iface in service.interfaces:
        for m in iface.methods:
            if m.wire is None:
                continue
            if m.wire not in found:
                found[m.wire] = Route(m.wire, m.echo, m, [])
            found[m.wire].candidates.append((iface, m))
    # Longest paths first, then by text, so that a longer path is never shadowed.
    return sorted(found.values(), key=lambda r: (-len(r.wire), r.wire))


def usage_literals(service: Service) -> list[str]:
    """The service's answer to `help`, one line per request path in the IDL's order, as C++
    string literals (JSON's escapes are C++'s for ASCII)."""
    return [json.dumps(line) for line in help_lines(service)]


def member(iface: Interface) -> str:
    return iface.name.lower()


def local_type(f: Field) -> str:
    return "std::int32_t" if f.type.name == "joint" and not f.per_axis else value_type(f)


def reader(f: Field) -> str:
    return "rpc::read_vocab" if f.type.name == "vocab" and not f.per_axis else "read"


def writer(f: Field) -> str:
    return "rpc::write_vocab" if f.type.name == "vocab" and not f.per_axis else "write"


def read_condition(r: Route) -> str:
    n = len(r.wire)
    return " ||\n      ".join(f"!{reader(a)}(req[{n + k}], {param_name(a)})"
                               for k, a in enumerate(r.method.args))


def call_args(m: Method) -> str:
    return ", ".join(param_name(f) for f in m.args + m.results)


def ok_tail(m: Method, service: Service) -> bool:
    """Whether a successful reply ends in [ok]: not a stamped one, not one with the IDL's own
    reply head, and never in a scoped service (YARP's frame grabbers answer a command with an
    empty bottle)."""
    stamped = bool(m.results) and m.stamp
    return not stamped and m.reply_head is None and service.replies != "scoped"


def failure(service: Service) -> str:
    """The vocab of a failed or unknown request: [nak] in scoped services, as YARP's
    frameGrabber_nws_yarp answers, else [fail] as its control boards do."""
    return "nak" if service.replies == "scoped" else "fail"


def route_init(r: Route, service: Service) -> str:
    path = ", ".join(f'vocab("{v}")' for v in r.wire)
    stamped = "true" if r.method.results and r.method.stamp else "false"
    tail = "true" if ok_tail(r.method, service) else "false"
    command = "false" if r.method.results else "true"
    return f"{{{{{path}}}, {len(r.wire)}, {stamped}, {tail}, {command}, &{r.handler}}}"


def command_routes(service: Service) -> list:
    """The command port's heads, longest first (a longer head is never shadowed)."""
    if not service.command:
        return []
    return sorted(service.command.routes, key=lambda r: (-len(r[0]), r[0]))


def class_name(service: Service, role: str = "Server") -> str:
    return "".join(p.capitalize() for p in service.name.split("_")) + role


def client_methods(service: Service) -> list:
    """One implementation per C++ signature: methods shared by several interfaces (getAxes,
    setRefAcceleration...) are one override, sent on the path of the first interface listing it."""
    seen: dict = {}
    for iface in service.interfaces:
        for m in iface.methods:
            key = (m.cpp_name, tuple((f.type.name, f.per_axis) for f in m.args),
                   tuple((f.type.name, f.per_axis) for f in m.results))
            seen.setdefault(key, m)
    return list(seen.values())



def headers(idl: Idl) -> dict[str, str]:
    """The public headers: the wire types, and each service's server and client class."""
    env, helpers = _environment()
    sources = [f for f in all_sources(idl) if any(t.mark.file == f for t in idl.enums + idl.structs)]
    out = {"wire_types.hpp": env.get_template("wire_types.hpp.j2").render(
        header=line_comment_header("//", "BSD-3-Clause", sources), idl=idl, **helpers)}
    for s in idl.services:
        ctx = _service_context(s, helpers)
        out[f"{s.name}_server.hpp"] = env.get_template("server.hpp.j2").render(**ctx)
        out[f"{s.name}_client.hpp"] = env.get_template("client.hpp.j2").render(**ctx)
    return out


def sources(idl: Idl) -> dict[str, str]:
    """Each service's server dispatch and client implementation."""
    env, helpers = _environment()
    out = {}
    for s in idl.services:
        ctx = _service_context(s, helpers)
        out[f"{s.name}_server.cpp"] = env.get_template("server.cpp.j2").render(**ctx)
        out[f"{s.name}_client.cpp"] = env.get_template("client.cpp.j2").render(**ctx)
    return out


def _environment():
    env = environment(__file__)
    helpers = dict(failure=failure, usage_literals=usage_literals, command_routes=command_routes, cpp_type=cpp_type, client_methods=client_methods, cpp_signature=cpp_signature, routes=routes, route_init=route_init, read_condition=read_condition, call_args=call_args, member=member, local_type=local_type, reader=reader,
                   writer=writer, param_name=param_name, class_name=class_name,
                   header_name=header_name, identifier=identifier, vocab_text=vocab_text)
    return env, helpers


def _service_context(s, helpers: dict) -> dict:
    files = sorted({s.file} | {i.file for i in s.interfaces} |
                   {t.mark.file for i in s.interfaces for t in list(i.enums) + list(i.structs)})
    header = line_comment_header("//", "BSD-3-Clause", files)
    max_path = max([len(r.wire) for r in routes(s)] + [len(h) for h, _ in command_routes(s)] +
                   [len(s.protocol.wire) if s.protocol else 1, len(s.introspection or ())])
    return dict(header=header, s=s, max_path=max_path, **helpers)
