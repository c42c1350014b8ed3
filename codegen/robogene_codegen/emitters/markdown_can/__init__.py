# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Markdown tables of each CAN protocol and board configuration, for docs/generated/can/."""
from __future__ import annotations

from ...can.model import CanField, CanProtocol
from ...idl.model import Idl
from ..common import environment, html_comment_header



def number(x: float) -> str:
    return str(int(x)) if float(x).is_integer() else repr(float(x))


def layout(fields: list[CanField]) -> str:
    """`b1-4 position int32 count` lines of a payload, one per field."""
    if not fields:
        return "—"
    parts = []
    for f in fields:
        span = f"{f.byte}" if f.size == 1 else f"{f.byte}-{f.byte + f.size - 1}"
        scale = ""
        if f.scaled:
            scale = f" ×{number(f.scale)}" + (f" {f.offset:+g}" if f.offset else "")
        unit = f" {f.unit}" if f.unit else ""
        parts.append(f"[{span}] `{f.name}` {f.type_name}{unit}{scale}")
    return "<br>".join(parts)


def brief(fields: list[CanField]) -> str:
    """`position` (count), `speed` (count/s): a payload's fields without their byte layout."""
    if not fields:
        return "—"
    return ", ".join(f"`{f.name}`" + (f" ({f.unit or f.type_name})" if f.unit or f.enum or f.flags else "")
                     for f in fields)


def _environment():
    env = environment(__file__)
    env.globals.update(layout=layout, number=number, brief=brief)
    return env


# The protocol whose summary docs/electronics.md carries.
SUMMARY_PROTOCOL = "motor_control"


def summary(p: CanProtocol) -> str:
    """The identifier layout, the classes and the command and broadcast tables in brief."""
    return _environment().get_template("protocol_summary.md.j2").render(p=p)


def summary_blocks(idl: Idl) -> dict[str, str]:
    """The CAN_PROTOCOL block of docs/electronics.md: the summary of the head's protocol."""
    protocol = next((p for p in idl.can_protocols if p.name == SUMMARY_PROTOCOL), None)
    if protocol is None:
        raise LookupError(f"interfaces/idl: no can_protocol named {SUMMARY_PROTOCOL!r}")
    return {"CAN_PROTOCOL": summary(protocol)}


def emit(idl: Idl) -> dict[str, str]:
    env = _environment()
    out = {}
    for p in idl.can_protocols:
        out[f"{p.name}.md"] = env.get_template("protocol.md.j2").render(
            p=p, header=html_comment_header("CC-BY-SA-4.0", [p.file]))
    for c in idl.board_configs:
        out[f"{c.name}.md"] = env.get_template("board_config.md.j2").render(
            c=c, header=html_comment_header("CC-BY-SA-4.0", c.sources))
    return out
