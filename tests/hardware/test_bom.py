# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""BOM: quantities come from the CAD assembly and the board BOMs, costs add up, and a part the catalog
lacks (or a malformed board BOM) stops the build with a message naming it."""
import csv
import io
import math
from collections import Counter

import pytest
import yaml

from robogene_bom import board, build, catalog, collect, render
from robogene_head.parts import mounts

from conftest import DATA


@pytest.fixture(scope="module")
def cat():
    return catalog.load()


def test_catalog_loads_with_sane_breaks(cat):
    for item in cat.items.values():
        assert item.breaks[0][0] == 1
        assert item.unit_price(1) == item.breaks[0][1]
        assert item.unit_price(10 ** 6) == item.breaks[-1][1]


def test_quantities_are_counted_from_the_assembly(params, assembly, cat):
    bom = collect.collect(assembly.parts, mounts.belts(params), [], cat)
    qty = {line.item.key: line.per_head for line in bom.lines}
    expected = Counter(p.design for p in assembly.parts if p.kind == "purchased")
    for key, n in expected.items():
        assert qty[key] == n
    # Cross-check against the drives in the parameter file: one motor, gearhead and encoder per chain joint.
    motors = Counter(params.drive(j).text("motor") for j in params.joints)
    for key, n in motors.items():
        assert qty[key] == n
    bearings = Counter()
    for j in params.joints:
        d = params.drive(j)
        if d.has("bearing"):
            bearings[d.text("bearing")] += int(d.num("bearings"))
    for key, n in bearings.items():
        assert qty[key] == n
    assert qty["raspberrypi-SC0872"] == 2
    assert {"xl-belt-35T", "xl-belt-53T"} <= set(qty)


def test_costs_follow_the_price_breaks(params, assembly, cat):
    bom = collect.collect(assembly.parts, mounts.belts(params), [], cat)
    one = sum(l.per_head * l.item.unit_price(l.per_head) for l in bom.lines)
    assert bom.cost_per_head(1) == pytest.approx(one)
    assert bom.cost_per_head(25) < bom.cost_per_head(1)
    rows = list(csv.DictReader(io.StringIO(render.to_csv(bom, 25))))
    assert sum(float(r["line_cost_batch"]) for r in rows) == pytest.approx(bom.cost_per_head(25) * 25, abs=0.05)


def test_missing_catalog_part_is_named(params, assembly, tmp_path):
    data = yaml.safe_load(catalog.DEFAULT_PATH.read_text())
    del data["parts"]["skf-61800-2RS"]
    path = tmp_path / "catalog.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(catalog.CatalogError, match=r"no entry for 'skf-61800-2RS' \(needed by CAD part neck_pitch_bearing_right\)"):
        collect.collect(assembly.parts, mounts.belts(params), [], catalog.load(path))


def test_bad_catalog_entry_is_named(tmp_path):
    data = yaml.safe_load(catalog.DEFAULT_PATH.read_text())
    data["parts"]["skf-626-2Z"]["breaks"] = [[5, 1.0]]
    path = tmp_path / "catalog.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(catalog.CatalogError, match=r"parts\.skf-626-2Z\.breaks\[0\]: the first break must start at quantity 1"):
        catalog.load(path)


def _catalog_with_board_parts(tmp_path):
    data = yaml.safe_load(catalog.DEFAULT_PATH.read_text())
    data["parts"].update(yaml.safe_load((DATA / "board-parts.yaml").read_text()))
    path = tmp_path / "catalog-with-board.yaml"
    path.write_text(yaml.safe_dump(data))
    return path


def test_board_bom_merges_into_the_head_bom(params, assembly, tmp_path):
    path = _catalog_with_board_parts(tmp_path)
    cat = catalog.load(path)
    out = tmp_path / "bom"
    bom = build.write_package(params, assembly.parts, [DATA / "head-neck-board-bom.csv"], out, batch=5, catalog_path=path)
    qty = {l.item.key: l.per_head for l in bom.lines}
    copies = int(params.root.node("boards").num("count"))   # one board design, built `count` times per head
    assert qty["ti-DRV8876PWPR"] == 2 * copies and qty["yageo-RC0603FR-0710KL"] == 6 * copies
    assert qty[params.root.node("boards").text("pcb")] == copies
    rows = list(csv.DictReader((out / "robogene-head-bom.csv").open()))
    assert {r["mpn"] for r in rows} >= {"DRV8876PWPR", "RC0603FR-0710KL", "2342S012CR"}
    assert "head-neck-board-bom" in (out / "robogene-head-bom.md").read_text()
    assert cat.items["ti-DRV8876PWPR"].unit_price(10) == 2.9


def test_board_part_missing_from_catalog_is_named(params, assembly, tmp_path):
    with pytest.raises(catalog.CatalogError, match=r"mpn 'DRV8876PWPR' \(needed by head-neck-board-bom.csv:2, U1,U2\)"):
        build.write_package(params, assembly.parts, [DATA / "head-neck-board-bom.csv"], tmp_path, batch=5)


def test_malformed_board_bom_is_named(tmp_path):
    path = tmp_path / "b.csv"
    path.write_text("Reference,Value,Footprint,MPN,Qty\nR1,10k,R_0603,RC0603FR-0710KL,two\n")
    with pytest.raises(board.BoardBomError, match=r"b.csv:2: Qty 'two' is not a whole number"):
        board.read(path)
    path.write_text("Reference,Value,MPN\nR1,10k,X\n")
    with pytest.raises(board.BoardBomError, match=r"b.csv:1: header lacks column\(s\) Footprint, Qty"):
        board.read(path)


def test_package_bom_files(fab, params, assembly):
    import json
    rows = list(csv.DictReader((fab / "bom" / "robogene-head-bom.csv").open()))
    qty = {r["key"]: float(r["qty_per_head"]) if r["unit"] == "m" else int(r["qty_per_head"]) for r in rows}
    expected = Counter(p.design for p in assembly.parts if p.kind == "purchased")
    assert all(expected[k] == 1 for k, _, _ in mounts.belts(params))   # each belt is a part of the assembly
    sources = json.loads((fab / "bom" / "sources.json").read_text())
    # The package merged the motor board's BOM once per board in the assembly, with one bare PCB each.
    copies = int(params.root.node("boards").num("count"))
    assert [b["copies"] for b in sources["board_boms"]] == [copies] and copies == 3
    assert sum(1 for p in assembly.parts if p.kind == "board") == copies
    assert qty[params.root.node("boards").text("pcb")] == copies
    board_rows = list(csv.DictReader(open(sources["board_boms"][0]["path"], encoding="utf-8-sig")))
    assert len(board_rows) > 20
    by_mpn = catalog.load(sources["catalog"]).by_mpn()
    for b in sources["board_boms"]:   # recount the board parts straight from the KiCad CSV
        for row in csv.DictReader(open(b["path"], encoding="utf-8-sig")):
            expected[by_mpn[row["MPN"].casefold()].key] += int(row["Qty"]) * b["copies"]
        expected[params.root.node("boards").text("pcb")] += b["copies"]
    # The harness's parts (its plan in the package) and what the head needs besides its own parts (bom.system).
    for line in json.loads((fab / "harness" / "harness.json").read_text())["bom"]:
        expected[line["key"]] += line["per_head"]
    for key, n, _ in build.system_lines(params, copies):
        expected[key] += n
    assert set(qty) == set(expected)
    assert all(qty[k] == pytest.approx(expected[k], abs=0.006) for k in qty)
    batch = int(params.root.node("bom").num("batch"))
    for r in rows:   # wire is ordered in whole metres for the batch
        per_head = float(r["qty_per_head"])
        assert int(r["qty_batch"]) == (math.ceil(batch * per_head - 1e-9) if r["unit"] == "m" else batch * int(per_head))
    md = (fab / "bom" / "robogene-head-bom.md").read_text()
    assert md.count("\n| ") >= len(rows)
    html = (fab / "bom" / "robogene-head-bom.html").read_text()
    assert html.startswith("<!DOCTYPE html>") and html.count("<tr>") > len(rows)


def test_parts_bought_by_length_are_ordered_in_whole_metres(params, assembly, cat):
    bom = collect.collect(assembly.parts, mounts.belts(params), [], cat,
                          extras=[("wire-28awg-ptfe", 0.35, "test"), ("wire-28awg-ptfe", 0.3, "test")])
    wire = next(l for l in bom.lines if l.item.key == "wire-28awg-ptfe")
    assert wire.per_head == pytest.approx(0.65) and wire.ordered(1) == 1 and wire.ordered(5) == 4
    row = next(r for r in csv.DictReader(io.StringIO(render.to_csv(bom, 5))) if r["key"] == "wire-28awg-ptfe")
    assert (row["unit"], row["qty_per_head"], row["qty_batch"]) == ("m", "0.65", "4")
    assert float(row["line_cost_batch"]) == pytest.approx(4 * cat.items["wire-28awg-ptfe"].unit_price(4))


def test_system_parts_are_listed(params):
    lines = build.system_lines(params, 3)
    keys = {k: n for k, n, _ in lines}
    assert keys["pcb-assembly-motor-board"] == 3 and keys["canable-2.0"] == 1 and keys["meanwell-GST90A12-P1M"] == 1


def test_making_the_parts_is_estimated_from_the_shop_rates(params, assembly, cat):
    from robogene_bom import making
    bom = collect.collect(assembly.parts, mounts.belts(params), [], cat)
    r = making.rates(params)
    density = params.root.node("materials")
    flange = next(m for m in bom.made if m.design == "neck_base_flange")
    stock = 1.0
    for size in flange.size_mm:
        stock *= size + 2 * r.stock_margin
    minutes = r.cycle_min + (stock - flange.volume_mm3) / 1000 / r.removal_cm3_per_min
    by_hand = stock * 1e-9 * 2700 * r.stock_per_kg + minutes / 60 * r.machining_per_h + r.setup_h * r.machining_per_h
    assert making.unit_cost(flange, 1, r, density.num(flange.material)) == pytest.approx(by_hand)
    # The set-up is shared by every piece of a batch: ten heads save nine tenths of it on each piece.
    saved = making.unit_cost(flange, 1, r, 2700) - making.unit_cost(flange, 10, r, 2700)
    assert saved == pytest.approx(r.setup_h * r.machining_per_h * 0.9)
    cup = next(m for m in bom.made if m.design == "eye_cup")
    assert making.unit_cost(cup, 1, r, 900) == pytest.approx(
        cup.volume_mm3 * 1e-9 * 900 * r.filament_per_kg + (cup.volume_mm3 / 1000 / r.deposit_cm3_per_h + r.print_setup_h)
        * r.printing_per_h)
    assert making.per_head(bom, params, 5) < making.per_head(bom, params, 1)
    md = render.to_markdown(bom, 5, build.made_costs(params, bom, 5))
    assert "Making the parts (estimate" in md and "not quotes" in md
