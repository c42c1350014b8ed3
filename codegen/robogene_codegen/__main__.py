# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""python -m robogene_codegen {generate,check,list,needs,fingerprints} [--root DIR] [--only NAME ...] [--fab DIR]

generate and check run the generators of codegen/generated-manifest.yaml (all of them, or those
--only names: a generator's name, or `idl` / `sources`); list prints every generated file or block
with its generator; needs prints the make targets the generators need built first."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .generate import GenerateError, render, stale, write
from .idl import IdlErrors
from .manifest import read

DEFAULT_ROOT = Path(__file__).resolve().parents[2]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="robogene_codegen", description=__doc__.splitlines()[0])
    parser.add_argument("command", choices=("generate", "check", "list", "needs", "fingerprints"))
    parser.add_argument("--root", type=Path, default=DEFAULT_ROOT,
                        help="repository root holding the manifest and interfaces/idl (default: this checkout)")
    parser.add_argument("--only", action="append", metavar="NAME",
                        help="run only this generator or group (idl: from the IDL; sources: needing no build)")
    parser.add_argument("--fab", type=Path, help="the fabrication package the doc tables come from "
                        "(default: ROOT/build/fab)")
    args = parser.parse_args(argv)
    root = args.root.resolve()
    try:
        manifest = read(root)
        if args.command == "list":
            for path, name in sorted(manifest.files.items()):
                print(f"{path}  {name}")
            for g in manifest.generators:
                for document, blocks in g.blocks:
                    print("".join(f"{document}#{b}  {g.name}\n" for b in blocks), end="")
            return 0
        if args.command == "needs":
            print(" ".join(sorted({g.needs for g in manifest.generators if g.needs})))
            return 0
        if args.command == "fingerprints":
            from .idl import compile_directory
            idl = compile_directory(root / "interfaces" / "idl", root=root)
            for item in idl.interfaces + idl.services:
                print(f"{item.name} {item.fingerprint}")
            return 0
        outputs = render(root, args.only, args.fab, manifest)
    except IdlErrors as exc:
        print(exc, file=sys.stderr)
        print(f"robogene_codegen: {len(exc.errors)} error(s)", file=sys.stderr)
        return 1
    except GenerateError as exc:
        for line in exc.problems:
            print(f"error: {line}", file=sys.stderr)
        print(f"robogene_codegen: {len(exc.problems)} problem(s); nothing written", file=sys.stderr)
        return 1
    if args.command == "generate":
        touched = write(root, outputs, args.only, manifest)
        print(f"robogene_codegen: {len(outputs)} files generated, {len(touched)} changed")
        for path in touched:
            print(f"  {path}")
        return 0
    problems = stale(root, outputs, args.only, manifest)
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
