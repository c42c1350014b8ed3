# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Prints one request of every path a service dispatches (from the IDL's wire tables), in the text
syntax `yarp rpc` reads, with example arguments: the requests sent to YARP 3.12.3 to make the
fixtures of this directory (README.md).

usage: requests_from_idl.py <service> [axes]"""
from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

# The wire tables alone (pure Python): no need for the compiled core.
_WIRE = Path(__file__).resolve().parents[3] / "runtime/python/robogene/dev/generated/wire.py"
_spec = importlib.util.spec_from_file_location("wire", _WIRE)
wire = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(wire)
INTERFACES, SERVICES, STRUCTS = wire.INTERFACES, wire.SERVICES, wire.STRUCTS

EXAMPLES = {"joint": "1", "float64": "0.25", "int32": "3", "bool": "1", "CameraFeature": "7",
            "FeatureMode": "2", "PidType": "[pos]", "ControlMode": "[pos]"}


def example(t: str, axes: int) -> str:
    if t.endswith("[]"):
        return "(" + " ".join(example(t[:-2], axes) for _ in range(axes)) + ")"
    if t in STRUCTS:
        return "(" + " ".join(f"{k + 1}.5" for k in range(len(STRUCTS[t]))) + ")"
    return EXAMPLES[t]


def main() -> int:
    service, axes = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 4
    _, names, protocol, _ = SERVICES[service]
    seen = set()
    if protocol:
        print(" ".join(f"[{w}]" for w in protocol[0]))
    for name in names:
        for method, (wire, _, args, _, _) in INTERFACES[name][1].items():
            if wire is None or wire in seen:
                continue
            seen.add(wire)
            print(" ".join([f"[{w}]" for w in wire] + [example(a, axes) for a in args]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
