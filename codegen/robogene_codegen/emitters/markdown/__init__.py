# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The Markdown reference of every interface and service, for docs/generated/interfaces/."""
from __future__ import annotations

from ...idl.model import Field, Idl, Method
from ..common import (all_sources, described, environment, html_comment_header,
                      interface_sources, param_name, vocab_int)



def field_text(f: Field) -> str:
    kind = f"{f.type.name}[axes]" if f.per_axis else f.type.name
    unit = f" ({f.unit})" if f.unit else ""
    default = f" = {f.default!r}" if f.has_default else ""
    return f"`{param_name(f)}`: {kind}{unit}{default}"


def request_text(m: Method) -> str:
    if not m.wire:
        return "local only"
    parts = [f"[{v}]" for v in m.wire]
    parts += [f"({param_name(a)}…)" if a.per_axis else f"<{param_name(a)}>" for a in m.args]
    return "`" + " ".join(parts) + "`"


def reply_text(m: Method) -> str:
    if not m.wire:
        return "—"
    if not m.results:
        return "`[ok]` / `[fail]`"
    values = " ".join(f"({param_name(r)}…)" if r.per_axis else f"<{param_name(r)}>" for r in m.results)
    echo = f"[{m.echo}]" if isinstance(m.echo, str) else f"<request[{m.echo}]>"
    stamp = " [tsta] <n> <t>" if m.stamp else ""
    return f"`[is] {echo} {values}{stamp} [ok]` / `[fail]`"


def cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def emit(idl: Idl) -> dict[str, str]:
    env = environment(__file__)
    env.filters["field_text"] = field_text
    helpers = dict(field_text=field_text, request_text=request_text, reply_text=reply_text,
                   described=described, cell=cell, vocab_int=vocab_int)
    out = {}
    for iface in idl.interfaces:
        out[f"{iface.name}.md"] = env.get_template("interface.md.j2").render(
            header=html_comment_header("CC-BY-SA-4.0", interface_sources(iface, idl)), iface=iface,
            **helpers)
    out[f"README.md"] = env.get_template("index.md.j2").render(
        header=html_comment_header("CC-BY-SA-4.0", all_sources(idl)), idl=idl, **helpers)
    return out
