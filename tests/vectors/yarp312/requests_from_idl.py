# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Prints one request of every path a service dispatches (from the IDL's wire tables), in the text
syntax `yarp rpc` reads, with example arguments: the requests sent to YARP 3.12.3 to make the
fixtures of this directory (README.md).

usage: requests_from_idl.py <service> [axes]"""
from __future__ import annotations

import sys
from pathlib import Path

# The IDL compiled by the code generator, as `make generate` compiles it: no need for the compiled core.
ROOT = Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "codegen"))
from robogene_codegen.idl import compile_directory  # noqa: E402

IDL = compile_directory(ROOT / "interfaces" / "idl", root=ROOT)
STRUCTS = {st.name: st.fields for st in IDL.structs}

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
    served = next(s for s in IDL.services if s.name == service)
    seen = set()
    if served.protocol:
        print(" ".join(f"[{w}]" for w in served.protocol.wire))
    for iface in served.interfaces:
        for method in iface.methods:
            if method.wire is None or tuple(method.wire) in seen:
                continue
            seen.add(tuple(method.wire))
            args = [example(a.type.name + ("[]" if a.per_axis else ""), axes) for a in method.args]
            print(" ".join([f"[{w}]" for w in method.wire] + args))
    return 0


if __name__ == "__main__":
    sys.exit(main())
