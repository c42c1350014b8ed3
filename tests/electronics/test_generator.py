# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The committed schematic and project files are exactly what the generator writes from design.py."""
import json
import pathlib
import sys

import pytest

import design
import gen_project
import gen_schematic
from conftest import BOARD_DIR, NAME, ROOT, SCH
from kicad_lib import FOOTPRINT_DIR
from sexpr import SexprError, parse

ROOT_FP = pathlib.Path(FOOTPRINT_DIR)


def test_schematic_is_regenerated_byte_for_byte(tmp_path):
    out = tmp_path / "x.kicad_sch"
    gen_schematic.main(str(out))
    assert out.read_bytes() == SCH.read_bytes(), "run hardware/electronics/generator/regenerate.sh and commit"


def test_project_files_are_regenerated(tmp_path):
    """Library tables byte for byte; the .kicad_pro is rewritten by pcbnew on save, so its design
    rules and net classes are compared as data."""
    gen_project.main(str(tmp_path), NAME)
    for name in ("sym-lib-table", "fp-lib-table"):
        assert (tmp_path / name).read_bytes() == (BOARD_DIR / name).read_bytes(), name
    fresh = json.loads((tmp_path / f"{NAME}.kicad_pro").read_text())
    committed = json.loads((BOARD_DIR / f"{NAME}.kicad_pro").read_text())
    assert committed["net_settings"]["netclass_patterns"] == fresh["net_settings"]["netclass_patterns"]
    by_name = {c["name"]: c for c in committed["net_settings"]["classes"]}
    for cls in fresh["net_settings"]["classes"]:
        for key in ("track_width", "clearance", "via_diameter", "via_drill"):
            assert by_name[cls["name"]][key] == cls[key], (cls["name"], key)
    rules = committed["board"]["design_settings"]["rules"]
    for key, value in fresh["board"]["design_settings"]["rules"].items():
        assert rules[key] == value, key


def test_regenerating_over_the_committed_project_changes_nothing(tmp_path):
    pro = f"{NAME}.kicad_pro"
    (tmp_path / pro).write_bytes((BOARD_DIR / pro).read_bytes())
    gen_project.main(str(tmp_path), NAME)
    assert (tmp_path / pro).read_bytes() == (BOARD_DIR / pro).read_bytes()


def test_every_part_has_order_codes_and_a_library_footprint():
    for part in design.parts():
        lib, name = part.footprint.split(":")
        assert (ROOT_FP / f"{lib}.pretty" / f"{name}.kicad_mod").exists(), part.footprint
        if part.in_bom:
            assert part.mpn and part.manufacturer, part.ref


def test_every_bom_part_is_in_the_head_catalog():
    """The head BOM merges this board's BOM by MPN; a part the catalog lacks stops `make fab`."""
    sys.path.insert(0, str(ROOT / "hardware" / "bom"))
    from robogene_bom import catalog
    by_mpn = catalog.load().by_mpn()
    missing = sorted({f"{p.mpn} ({p.ref})" for p in design.parts() if p.in_bom and p.mpn.casefold() not in by_mpn})
    assert not missing, f"not in hardware/bom/catalog.yaml: {', '.join(missing)}"


def test_schematic_layout_rejects_a_block_in_the_title_block(monkeypatch):
    title, _x, _y, width = gen_schematic.BLOCKS["axis2"]
    _paper, page_w, page_h = gen_schematic.PAPER
    monkeypatch.setitem(gen_schematic.BLOCKS, "axis2", (title, page_w - 130, page_h - 60, width))
    with pytest.raises(ValueError, match=r"U7 \(axis2\) (leaves the drawing|runs into the title block)"):
        gen_schematic.build()


def test_net_classes_match_real_net_names():
    nets = {n for p in design.parts() for n in p.pins.values() if n}
    for cname, *_rest, members in gen_project.NET_CLASSES:
        for pattern in members:
            name = pattern.lstrip("/")
            assert name in nets, f"net class {cname} names {pattern}, no such net"
            assert pattern.startswith("/") == (name not in design.POWER_NETS), pattern


def test_stacked_pins_with_different_nets_are_rejected():
    bad = design.Part("U99", "Transistor_FET:DMP3013SFV", "x", "Package_SON:Diodes_PowerDI3333-8", "m", "m",
                      {"1": "+12V", "2": "GND", "3": "+12V", "4": "G", "5": "D"}, "power")
    with pytest.raises(ValueError, match=r"U99: stacked pins \['1', '2', '3'\]"):
        gen_schematic.place(gen_schematic.Sheet(), bad, 0, 0)


def test_a_pin_without_a_net_is_rejected():
    bad = design.Part("R99", "Device:R", "1k", "Resistor_SMD:R_0603_1608Metric", "m", "m", {"1": "A"}, "power")
    with pytest.raises(ValueError, match=r"R99: pin 2 \(~\) of Device:R has no net"):
        gen_schematic.place(gen_schematic.Sheet(), bad, 0, 0)


@pytest.mark.parametrize("text, where", [("(a (b c)", r"1 list\(s\) not closed"), ("(a))", "1:4: unbalanced"),
                                         ("(a)\n (b)", "2:4: more than one top-level"), ("x", "1:1: atom outside")])
def test_sexpr_errors_name_the_place(text, where):
    with pytest.raises(SexprError, match=where):
        parse(text, "t.kicad_sch")


def test_project_json_is_loadable():
    pro = json.loads((BOARD_DIR / f"{NAME}.kicad_pro").read_text())
    assert {c["name"] for c in pro["net_settings"]["classes"]} == {"Default", "Chain", "Input", "Power", "Motor", "Supply"}
