# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Keep the CAN protocol tables in docs/electronics.md equal to the IDL
(python -m robogene_codegen.emitters.markdown_can.doc_blocks --check | --update).

The doc is written by hand except for the block between <!-- CAN_PROTOCOL:BEGIN ... --> and
<!-- CAN_PROTOCOL:END -->, which holds `summary()` of the head's protocol. --check (the tests,
`make check-generated`) fails when the block differs from what the IDL gives; --update (`make
generate`) rewrites it."""
from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

from ...idl import IdlErrors, compile_directory
from . import summary

REPO = Path(__file__).resolve().parents[4]
DOC = Path("docs") / "electronics.md"
PROTOCOL = "motor_control"
BLOCK = "CAN_PROTOCOL"


def wanted_blocks(root: Path) -> dict[str, str]:
    idl = compile_directory(root / "interfaces" / "idl", root / "interfaces" / "idl" / "idl.schema.json", root=root)
    protocol = next((p for p in idl.can_protocols if p.name == PROTOCOL), None)
    if protocol is None:
        raise LookupError(f"{root / 'interfaces' / 'idl'}: no can_protocol named {PROTOCOL!r}")
    return {BLOCK: summary(protocol)}


def sync(doc_text: str, blocks: dict[str, str], doc_name: str) -> str:
    """`doc_text` with every block's body replaced; the markers themselves are kept."""
    for name, body in blocks.items():
        pattern = re.compile(rf"(<!-- {name}:BEGIN[^>]*-->\n).*?(<!-- {name}:END -->)", re.S)
        if len(pattern.findall(doc_text)) != 1:
            raise ValueError(f"{doc_name}: expected one <!-- {name}:BEGIN ... --> ... <!-- {name}:END --> block")
        doc_text = pattern.sub(lambda m: m.group(1) + body + m.group(2), doc_text)
    return doc_text


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="doc_blocks", description=__doc__.splitlines()[0])
    ap.add_argument("--root", type=Path, default=REPO, help="repository root holding interfaces/idl")
    ap.add_argument("--doc", type=Path, help="the document (default: ROOT/docs/electronics.md)")
    mode = ap.add_mutually_exclusive_group(required=True)
    mode.add_argument("--check", action="store_true")
    mode.add_argument("--update", action="store_true")
    args = ap.parse_args(argv)
    doc = args.doc or args.root / DOC
    try:
        current = doc.read_text(encoding="utf-8")
        wanted = sync(current, wanted_blocks(args.root), str(doc))
    except IdlErrors as exc:
        print(exc, file=sys.stderr)
        return 1
    except (OSError, ValueError, LookupError) as exc:
        print(f"doc_blocks: {exc}", file=sys.stderr)
        return 1
    if args.update:
        if wanted != current:
            doc.write_text(wanted, encoding="utf-8")
            print(f"doc_blocks: rewrote the {BLOCK} block of {doc}")
        return 0
    if wanted != current:
        print(f"{doc}: the {BLOCK} block differs from the IDL; run `make generate`", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
