# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Content-hash cache: an output is rebuilt only when the hash of what it is made from changed
or when one of its files is missing."""
from __future__ import annotations

import hashlib
import json
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
