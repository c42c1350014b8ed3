# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""docs/electronics.md carries the CAN protocol in brief (identifier layout, classes, commands,
broadcasts) in a block generated from the IDL: the block is current, says what the protocol file
says (read here with yaml, not through the generator), and goes stale when the protocol changes. The block is
the manifest's `can-protocol-summary` generator, checked and rewritten like every generated file."""
import re
import shutil

import pytest
import yaml

from conftest import ROOT
from robogene_codegen.__main__ import main

ONLY = ["--only", "can-protocol-summary"]

PROTOCOL_FILE = ROOT / "interfaces" / "idl" / "can_motor_control.yaml"
DOC = ROOT / "docs" / "electronics.md"


def block(text: str) -> str:
    m = re.search(r"<!-- CAN_PROTOCOL:BEGIN[^>]*-->\n(.*?)<!-- CAN_PROTOCOL:END -->", text, re.S)
    assert m, "docs/electronics.md has no CAN_PROTOCOL block"
    return m.group(1)


def tables(text: str) -> dict[str, list[list[str]]]:
    """Every table of `text` by the first cell of its header row: its other rows, as cells."""
    found, current = {}, None
    for line in text.splitlines():
        if not line.startswith("|"):
            current = None
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if current is None:
            current = found.setdefault(cells[0], [])
        elif not line.startswith("|---"):
            current.append(cells)
    return found


def names(fields, named_types: set[str]) -> str:
    """`position` (count), `mode` (ControlMode): each field with its unit, or its enum or flags type."""
    def one(f) -> str:
        kind = f.get("unit") or (f["type"] if f["type"] in named_types else None)
        return f"`{f['name']}`" + (f" ({kind})" if kind else "")
    return ", ".join(one(f) for f in fields or []) or "—"


def test_the_block_is_current(capsys):
    assert main(["check", *ONLY]) == 0, capsys.readouterr().err


def test_the_block_says_what_the_protocol_file_says():
    idl = yaml.safe_load(PROTOCOL_FILE.read_text())
    found = tables(block(DOC.read_text()))
    layout = idl["id_layout"]
    assert found["identifier bits"] == [["field", *(f["name"] for f in layout)]]
    bits = " | ".join(f"{f['shift'] + f['bits'] - 1}..{f['shift']}" for f in layout)
    assert f"| identifier bits | {bits} |" in DOC.read_text()  # the header row
    assert {r[0]: r[1:3] for r in found["class"]} == {
        str(c["value"]): [c["name"], "destination address" if c["addressing"] == "destination" else "message type"]
        for c in idl["classes"]}
    commands = {r[1]: r for r in found["code"]}
    broadcasts = {r[1]: r for r in found["type"]}
    # BroadcastMask is the flags type the compiler derives from the broadcasts (one bit per type).
    named_types = {t["name"] for t in idl["enums"] + idl["flags"]} | {"BroadcastMask"}
    expected_commands = [c for k in idl["classes"] for c in k.get("commands", [])]
    expected_broadcasts = [b for k in idl["classes"] for b in k.get("broadcasts", [])]
    assert len(commands) == len(expected_commands) == 37  # 31 motor-control commands, 6 of the bootloader
    assert len(broadcasts) == len(expected_broadcasts) == 6
    for c in expected_commands:
        row = commands[f"`{c['name']}`"]
        assert row[0] == f"`0x{c['code']:02X}`", row
        assert row[2:] == [names(c.get("request"), named_types), names(c.get("reply"), named_types)], row
    for b in expected_broadcasts:
        row = broadcasts[f"`{b['name']}`"]
        assert row[0] == str(b["code"]) and row[2] == f"{b['period_ms']} ms", row
        assert row[3] == names(b["fields"], named_types), row


@pytest.fixture
def tree(tmp_path):
    """A copy of what the block depends on: the IDL (and the head parameters it reads) and the doc."""
    root = tmp_path / "tree"
    shutil.copytree(ROOT / "interfaces", root / "interfaces")
    (root / "codegen").mkdir()
    shutil.copy(ROOT / "codegen" / "generated-manifest.yaml", root / "codegen")
    (root / "hardware").mkdir()
    shutil.copy(ROOT / "hardware" / "head-parameters.yaml", root / "hardware" / "head-parameters.yaml")
    (root / "docs").mkdir()
    shutil.copy(DOC, root / "docs" / "electronics.md")
    return root


def test_a_protocol_change_makes_the_block_stale_and_update_rewrites_it(tree, capsys):
    proto = tree / "interfaces" / "idl" / "can_motor_control.yaml"
    anchor = "      - name: get_firmware_version\n"
    proto.write_text(proto.read_text().replace(anchor, "      - name: get_supply_voltage\n        code: 120\n"
                                               "        doc: Read the motor supply voltage.\n        reply:\n"
                                               "          - {name: voltage, type: uint16, unit: V, scale: 0.001}\n"
                                               + anchor))
    assert main(["check", "--root", str(tree), *ONLY]) == 1
    assert "stale: docs/electronics.md: differs from what its generator writes" in capsys.readouterr().err

    assert main(["generate", "--root", str(tree), *ONLY]) == 0
    assert main(["check", "--root", str(tree), *ONLY]) == 0
    updated = (tree / "docs" / "electronics.md").read_text()
    assert "| `0x78` | `get_supply_voltage` | — | `voltage` (V) |" in block(updated)
    # Only the block changed: the hand-written text around it is as it was.
    original = DOC.read_text()
    assert updated.replace(block(updated), "") == original.replace(block(original), "")


def test_a_doc_without_the_markers_is_reported(tree, capsys):
    doc = tree / "docs" / "electronics.md"
    doc.write_text(doc.read_text().replace("<!-- CAN_PROTOCOL:END -->", ""))
    before = doc.read_text()
    assert main(["generate", "--root", str(tree), *ONLY]) == 1
    err = capsys.readouterr().err
    assert "error: docs/electronics.md: no <!-- CAN_PROTOCOL:BEGIN ... --> ... <!-- CAN_PROTOCOL:END --> block" in err, err
    assert "nothing written" in err and doc.read_text() == before
