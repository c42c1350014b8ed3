# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Content-hash cache: an output is rebuilt only when the hash of what it is made from changed
or when one of its files is missing."""
from __future__ import annotations

import hashlib
import json
import sys
import types
from pathlib import Path


def digest(*items) -> str:
    h = hashlib.sha256()
    for item in items:
        h.update(json.dumps(item, sort_keys=True, default=str).encode() if not isinstance(item, (bytes, str)) else
                 (item.encode() if isinstance(item, str) else item))
        h.update(b"\0")
    return h.hexdigest()


class Cache:
    def __init__(self, path: Path):
        self.path = path
        try:
            self.state = json.loads(path.read_text())
        except (OSError, ValueError):
            self.state = {}

    def fresh(self, key: str, value: str, outputs: list[Path]) -> bool:
        return self.state.get(key) == value and all(p.exists() for p in outputs)

    def record(self, key: str, value: str) -> None:
        self.state[key] = value
        self.path.parent.mkdir(parents=True, exist_ok=True)
        tmp = self.path.with_suffix(".tmp")
        tmp.write_text(json.dumps(self.state, indent=1, sort_keys=True))
        tmp.replace(self.path)


# Part builders (robogene_head.parts.*) are left out of code digests: what they make is hashed shape by shape in
# the geometry key.
_GEOMETRY_PACKAGE = "parts"


def code_modules(*modules) -> dict[str, Path]:
    """These modules and every module of this package they use, followed through their imports (name -> file)."""
    seen: dict[str, Path] = {}
    unvisited = list(modules)
    while unvisited:
        module = unvisited.pop()
        name = module.__name__
        if name in seen or not name.startswith("robogene_head") or name.split(".")[1:2] == [_GEOMETRY_PACKAGE]:
            continue
        seen[name] = Path(module.__file__)
        for value in vars(module).values():
            used = value if isinstance(value, types.ModuleType) else sys.modules.get(getattr(value, "__module__", "")
                                                                                    or "")
            if isinstance(used, types.ModuleType):
                unvisited.append(used)
    return seen


def code_digest(*modules) -> str:
    """A digest of the source of code_modules(*modules): a cached output drawn by code that imports what changed is
    stale too (the step pictures once kept a stage() call that render.py no longer had, and only a fresh build ran
    it)."""
    files = code_modules(*modules)
    return digest(*[(name, hashlib.sha256(files[name].read_bytes()).hexdigest()) for name in sorted(files)])
