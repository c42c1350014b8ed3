# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The fabrication package built by `make electronics`, checked against the design it came from."""
import csv
import re
import struct

from conftest import PCB, SCH
from sexpr import find, find1, parse

GERBER_LAYERS = ["F_Cu", "In1_Cu", "In2_Cu", "B_Cu", "F_Mask", "B_Mask", "F_Silkscreen", "B_Silkscreen",
                 "F_Paste", "B_Paste", "Edge_Cuts"]


def _board():
    return parse(PCB.read_text(), str(PCB))


def _footprints():
    """ref -> (is_smd, excluded_from_pos, layer) read from the committed board file."""
    out = {}
    for fp in find(_board(), "footprint"):
        ref = next(p[2] for p in find(fp, "property") if p[1] == "Reference")
        attr = find1(fp, "attr") or []
        out[ref] = ("smd" in attr, "exclude_from_pos_files" in attr, find1(fp, "layer")[1])
    return out


def _schematic_symbols():
    """ref -> {field: value} for the real parts (power symbols and flags start with '#')."""
    out = {}
    for sym in find(parse(SCH.read_text(), str(SCH)), "symbol"):
        props = {p[1]: p[2] for p in find(sym, "property")}
        if not props["Reference"].startswith("#"):
            out[props["Reference"]] = dict(props, in_bom=find1(sym, "in_bom")[1] == "yes")
    return out


def test_gerber_set_is_complete_and_well_formed(fab):
    files = {p.name: p for p in (fab / "gerbers").iterdir()}
    for layer in GERBER_LAYERS:
        hits = [n for n in files if re.search(rf"-{layer}\.g[a-z0-9]+$", n)]
        assert len(hits) == 1, f"Gerber for {layer}: {hits} among {sorted(files)}"
        text = files[hits[0]].read_text()
        assert text.startswith("%TF.GenerationSoftware,KiCad"), hits[0]
        assert "%FSLAX" in text and text.rstrip().endswith("M02*"), f"{hits[0]} is not a complete Gerber"
    assert any(n.endswith(".gbrjob") for n in files), "Gerber job file missing"
    copper = files[next(n for n in files if n.endswith("-F_Cu.gtl"))].read_text()
    assert copper.count("D03*") >= 100, "front copper has almost no pad flashes"


def test_drill_files_list_every_plated_hole(fab):
    drills = sorted((fab / "gerbers").glob("*.drl"))
    assert {d.name.rsplit("-", 1)[-1] for d in drills} >= {"PTH.drl", "NPTH.drl"}
    pth = next(d for d in drills if d.name.endswith("-PTH.drl")).read_text()
    tools = dict(re.findall(r"^(T\d+)C([\d.]+)", pth, re.M))
    hits = len(re.findall(r"^X-?[\d.]+Y-?[\d.]+", pth, re.M))
    board = _board()
    vias = len(find(board, "via"))
    tht_pads = sum(1 for fp in find(board, "footprint") for pad in find(fp, "pad") if pad[2] == "thru_hole")
    assert tools and hits == vias + tht_pads, f"{hits} drill hits, board has {vias} vias + {tht_pads} THT pads"
    npth = next(d for d in drills if d.name.endswith("-NPTH.drl")).read_text()
    assert len(re.findall(r"^X-?[\d.]+Y-?[\d.]+", npth, re.M)) == 4, "the four M3 mounting holes"


def test_pick_and_place_lists_every_smd_part(fab):
    with open(fab / "pos.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    placed = {r["Ref"]: r for r in rows}
    smd = {ref for ref, (is_smd, excluded, _) in _footprints().items() if is_smd and not excluded}
    assert smd and smd <= set(placed), f"missing from pos.csv: {sorted(smd - set(placed))}"
    for ref in smd:
        x, y = float(placed[ref]["PosX"]), float(placed[ref]["PosY"])
        # KiCad writes page coordinates with y up; the board spans (100..190, 100..160) mm on the page
        assert 100 < x < 190 and -160 < y < -100, f"{ref} at ({x}, {y}) is outside the 90 x 60 mm board"
        assert placed[ref]["Side"] == "top"


def _references(cell):
    """KiCad's BOM writes runs of three or more consecutive references as a range: C31-C33."""
    refs = []
    for item in cell.split(","):
        run = re.fullmatch(r"([A-Z]+)(\d+)-\1(\d+)", item)
        refs += [f"{run[1]}{n}" for n in range(int(run[2]), int(run[3]) + 1)] if run else [item]
    return refs


def test_bom_reference_ranges_are_expanded():
    assert _references("C2,C31-C33,U9") == ["C2", "C31", "C32", "C33", "U9"]


def test_bom_has_order_codes_for_every_part_and_matches_the_schematic(fab):
    with open(fab / "bom.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert list(rows[0]) == ["Reference", "Value", "Footprint", "MPN", "Manufacturer", "Qty"]
    symbols = _schematic_symbols()
    refs = []
    for row in rows:
        group = _references(row["Reference"])
        assert row["MPN"].strip() and row["Manufacturer"].strip(), f"row without order code: {row}"
        assert int(row["Qty"]) == len(group), row
        for ref in group:
            assert symbols[ref]["MPN"] == row["MPN"] and symbols[ref]["Footprint"] == row["Footprint"], ref
        refs += group
    assert len(refs) == len(set(refs))
    assert set(refs) == {r for r, s in symbols.items() if s["in_bom"]}


def test_schematic_pdf_is_a_real_pdf(fab):
    data = (fab / "schematic.pdf").read_bytes()
    assert data.startswith(b"%PDF-") and b"%%EOF" in data[-64:]
    assert len(data) > 20_000


# Footprints whose 3-D model KiCad's kicad-packages3d does not ship (fetch-3d-models.sh warns).
MODELS_NOT_IN_KICAD = ("JST_VH_B2P-VH_1x02_P3.96mm_Vertical", "Fuse_Littelfuse-NANO2-451_453",
                       "R_Shunt_Vishay_WSK2512_6332Metric_T1.19mm")


def test_step_holds_the_board_and_every_available_component_model(fab):
    text = (fab / "board.step").read_text(errors="replace")
    assert text.startswith("ISO-10303-21;")
    assert "END-ISO-10303-21;" in text[-200:]
    models = re.findall(r'\(model "([^"]+)"', PCB.read_text())
    available = [m for m in models if not any(name in m for name in MODELS_NOT_IN_KICAD)]
    instances = text.count("NEXT_ASSEMBLY_USAGE_OCCURRENCE")
    assert instances == len(available) + 1, f"{instances} placed shapes, expected {len(available)} parts + the PCB"
    # origin at the board centre: the 90 x 60 mm outline spans exactly +-45 / +-30 mm
    pts = [tuple(map(float, m.groups())) for m in
           re.finditer(r"CARTESIAN_POINT\('[^']*',\(([-\d.E+]+),([-\d.E+]+),([-\d.E+]+)\)\)", text)]
    assert (min(p[0] for p in pts), max(p[0] for p in pts)) == (-45.0, 45.0)
    assert (min(p[1] for p in pts), max(p[1] for p in pts)) == (-30.0, 30.0)
    for product in ("robogene-motor-board_PCB", "LQFP-32_7x7mm_P0.8mm", "SOIC-8_3.9x4.9mm_P1.27mm"):
        assert f"PRODUCT('{product}'" in text, product


def test_render_is_a_png_of_the_requested_size(fab):
    data = (fab / "render.png").read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", data[16:24])
    # kicad-cli keeps the requested size within a few percent (it rounds to its tile grid)
    assert 1500 <= width <= 1600 and 1000 <= height <= 1100, (width, height)
    assert len(data) > 200_000, "render is suspiciously small (blank?)"
