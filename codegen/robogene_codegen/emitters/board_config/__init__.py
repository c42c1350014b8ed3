# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Board configurations: the CAN driver's .ini (Property format) and the firmware's C headers."""
from __future__ import annotations

from ...idl.model import Idl
from ..common import environment, line_comment_header, snake

def number(x: float) -> str:
    """Shortest text that reads back as the same double; integers without a fraction."""
    return str(int(x)) if float(x).is_integer() else repr(float(x))


def c_ident(name: str) -> str:
    return name.upper().replace("-", "_")


def _environment():
    env = environment(__file__)
    env.filters["snake"] = snake
    env.globals.update(number=number, c_ident=c_ident)
    return env


def ini(idl: Idl) -> dict[str, str]:
    """The CAN driver's and the simulator's configuration of each board config (Property format)."""
    env = _environment()
    return {f"{config.name}.ini": env.get_template("driver.ini.j2").render(
        c=config, header=line_comment_header("#", "BSD-3-Clause", config.sources)) for config in idl.board_configs}


def firmware(idl: Idl) -> dict[str, str]:
    """The firmware's C headers: each protocol's constants and each board config's table of boards."""
    env = _environment()
    out = {}
    for proto in idl.can_protocols:
        header = line_comment_header("//", "BSD-3-Clause", [proto.file])
        out[f"robogene_can_{proto.name}.h"] = env.get_template("protocol.h.j2").render(
            p=proto, header=header, guard=f"ROBOGENE_CAN_{proto.name.upper()}_H")
    for config in idl.board_configs:
        c_header = line_comment_header("//", "BSD-3-Clause", config.sources)
        out[f"robogene_{config.name}_board_config.h"] = env.get_template("board_config.h.j2").render(
            c=config, header=c_header, protocol_header=f"robogene_can_{config.protocol.name}.h",
            guard=f"ROBOGENE_{c_ident(config.name)}_BOARD_CONFIG_H")
    return out
