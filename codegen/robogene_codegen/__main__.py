# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""python -m robogene_codegen {generate,check,fingerprints} [--root DIR]"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .generate import render, stale, write
from .idl import IdlErrors

DEFAULT_ROOT = Path(__file__).resolve().parents[2]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="robogene_codegen", description=__doc__)
    parser.add_argument("command", choices=("generate", "check", "fingerprints"))
    parser.add_argument("--root", type=Path, default=DEFAULT_ROOT,
                        help="repository root holding interfaces/idl (default: this checkout)")
    args = parser.parse_args(argv)
    root = args.root.resolve()
    try:
        outputs = render(root)
    except IdlErrors as exc:
        print(exc, file=sys.stderr)
        print(f"robogene_codegen: {len(exc.errors)} error(s) in the IDL", file=sys.stderr)
        return 1
    if args.command == "generate":
        touched = write(root, outputs)
        print(f"robogene_codegen: {len(outputs)} files generated, {len(touched)} changed")
        for path in touched:
            print(f"  {path}")
        return 0
    if args.command == "fingerprints":
        from .idl import compile_directory
        idl = compile_directory(root / "interfaces" / "idl", root=root)
        for item in idl.interfaces + idl.services:
            print(f"{item.name} {item.fingerprint}")
        return 0
    problems = stale(root, outputs)
    for line in problems:
        print(f"stale: {line}", file=sys.stderr)
    if problems:
        print(f"robogene_codegen: {len(problems)} generated file(s) out of date; run `make generate`",
              file=sys.stderr)
        return 1
    print(f"robogene_codegen: all {len(outputs)} generated files are up to date")
    return 0


if __name__ == "__main__":
    sys.exit(main())
