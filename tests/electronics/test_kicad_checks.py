# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""KiCad's own checks on the committed design: ERC, and DRC with schematic parity and no unconnected items."""
import json
import re

from conftest import PCB, SCH


def _violations(report):
    return [v for sheet in report["sheets"] for v in sheet["violations"]]


def _describe(items):
    return "\n".join(f"{v['type']}: {v['description']} {[i['description'] for i in v['items']]}" for v in items)


def test_erc_has_no_violations_of_any_severity(kicad_cli, tmp_path):
    out = tmp_path / "erc.json"
    proc = kicad_cli("sch", "erc", "--format", "json", "--severity-all", "--exit-code-violations",
                     "-o", out, SCH, check=False)
    found = _violations(json.loads(out.read_text()))
    assert found == [], _describe(found)
    assert proc.returncode == 0


def test_drc_with_schematic_parity_is_clean(kicad_cli, tmp_path):
    out = tmp_path / "drc.json"
    proc = kicad_cli("pcb", "drc", "--format", "json", "--severity-all", "--schematic-parity",
                     "--exit-code-violations", "-o", out, PCB, check=False)
    report = json.loads(out.read_text())
    assert report["violations"] == [], _describe(report["violations"])
    assert report["unconnected_items"] == [], _describe(report["unconnected_items"])
    assert report["schematic_parity"] == [], _describe(report["schematic_parity"])
    assert proc.returncode == 0


def test_drc_exit_code_catches_a_broken_board(kicad_cli, tmp_path):
    """The gate can fail: the same board with one signal net's tracks removed must be reported as
    unconnected. (All of them: a single segment can lie wholly inside a pad, and removing it changes
    nothing.)"""
    text = PCB.read_text()
    signal_nets = set(re.findall(r'^\t\(net (\d+) "/', text, re.M))
    items = [(m.span(), re.search(r"\(net (\d+)\)", m.group(0)))
             for m in re.finditer(r"\n\t\((?:segment|via)\n.*?\n\t\)", text, re.S)]
    victim = next((net.group(1) for _, net in items if net and net.group(1) in signal_nets), None)
    assert victim, "no signal-net track segment found in the board file"
    for (start, end), net in reversed(items):
        if net and net.group(1) == victim:
            text = text[:start] + text[end:]
    broken = tmp_path / PCB.name
    broken.write_text(text)
    for side in ("kicad_pro", "kicad_sch"):
        src = PCB.with_suffix("." + side)
        (tmp_path / src.name).write_text(src.read_text())
    for table in ("sym-lib-table", "fp-lib-table"):
        (tmp_path / table).write_text((PCB.parent / table).read_text())
    out = tmp_path / "drc.json"
    proc = kicad_cli("pcb", "drc", "--format", "json", "--exit-code-violations", "-o", out, broken, check=False)
    assert proc.returncode == 5
    assert json.loads(out.read_text())["unconnected_items"]
