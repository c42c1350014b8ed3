# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Where the two implementations live and the private, loopback-only network each test gets:
its own YARP config/data/cache/runtime dirs and a yarp.conf naming a name server on a free port."""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def yarp_peer_venv() -> Path:
    return Path(os.environ.get("YARP_PEER_VENV", ROOT / ".yarp-venv"))


def yarp_tool(name: str) -> str:
    """The real executable: the venv's bin/<name> is a Python launcher that runs it as a child,
    which would put an extra process between the tests and the tool."""
    for path in sorted(yarp_peer_venv().glob(f"lib/python3*/site-packages/yarp/bin/{name}")):
        if os.access(path, os.X_OK):
            return str(path)
    raise FileNotFoundError(f"YARP peer tool {name} missing under {yarp_peer_venv()}: "
                            "build it with `make yarp-peer`")


def yarpdev() -> str:
    """yarpdev-static: the peer's yarpdev with its static devices registered (tests/interop/yarpdev_static)."""
    path = yarp_peer_venv() / "bin" / "yarpdev-static"
    if not os.access(path, os.X_OK):
        raise FileNotFoundError(f"{path} missing: build the YARP peer with `make yarp-peer`")
    return str(path)


def yarp_python() -> str:
    path = yarp_peer_venv() / "bin" / "python"
    if not os.access(path, os.X_OK):
        raise FileNotFoundError(f"{path} missing: build the YARP peer with `make yarp-peer`")
    return str(path)


def robogene_bin() -> str:
    path = Path(os.environ.get("ROBOGENE_BIN", ROOT / "build" / "bin" / "robogene"))
    if not os.access(path, os.X_OK):
        raise FileNotFoundError(f"robogene CLI {path} missing: build it with `make runtime` or set ROBOGENE_BIN")
    return str(path)


@dataclass
class PrivateNetwork:
    """A name-server port and an environment under which YARP tools and ours find it."""
    base: Path
    ns_port: int
    env: dict = field(default_factory=dict)

    @classmethod
    def create(cls, base: Path, ns_port: int) -> "PrivateNetwork":
        dirs = {var: base / sub for var, sub in (("YARP_CONFIG_HOME", "config"), ("YARP_DATA_HOME", "data"),
                                                  ("YARP_CACHE_HOME", "cache"), ("YARP_RUNTIME_DIR", "runtime"))}
        for d in dirs.values():
            d.mkdir(parents=True, exist_ok=True)
        (dirs["YARP_CONFIG_HOME"] / "yarp.conf").write_text(f"127.0.0.1 {ns_port} yarp\n")
        env = {k: v for k, v in os.environ.items()
               if not k.startswith("YARP_") and k not in ("XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME")}
        env.update({k: str(v) for k, v in dirs.items()})
        env.update({
            "HOME": str(base),                 # nothing may fall back to the real ~/.config/yarp
            "XDG_CONFIG_HOME": str(base / "xdg-config"),
            "XDG_DATA_HOME": str(base / "xdg-data"),
            "XDG_CACHE_HOME": str(base / "xdg-cache"),
            "YARP_COLORED_OUTPUT": "0",
            "PYTHONUNBUFFERED": "1",
        })
        return cls(base, ns_port, env)

    @property
    def server_arg(self) -> str:
        return f"127.0.0.1:{self.ns_port}"
