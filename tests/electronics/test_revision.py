# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""One revision string everywhere the board's revision is written: design.py (the source), the schematic's
and the board's title blocks, the board's silkscreen, the catalog's bare-board entry (and so the head BOM),
and the fabrication package (Gerber job file and every Gerber's project attribute). Rev B read "B" on the
schematic, "A" in the catalog and "?" in the Gerber job file."""
import json
import re

import yaml

import design
from conftest import PCB, ROOT, SCH
from sexpr import find, find1, parse


def _title_block_rev(path):
    tb = find1(parse(path.read_text(), str(path)), "title_block")
    rev = find1(tb, "rev") if tb else None
    return rev[1] if rev else None


def test_the_revision_is_a_single_letter():
    assert re.fullmatch(r"[A-Z]", design.REVISION), design.REVISION


def test_schematic_and_board_title_blocks():
    assert _title_block_rev(SCH) == design.REVISION
    assert _title_block_rev(PCB) == design.REVISION


def test_board_silkscreen():
    texts = [t[1] for t in find(parse(PCB.read_text(), str(PCB)), "gr_text")
             if find1(t, "layer")[1] in ("F.SilkS", "B.SilkS")]
    revs = [m.group(1) for t in texts for m in [re.search(r"\bREV\s+(\S+)", t, re.I)] if m]
    assert revs == [design.REVISION], texts


def _catalog_revision(catalog_text):
    parts = yaml.safe_load(catalog_text)["parts"]
    params = yaml.safe_load((ROOT / "hardware" / "head-parameters.yaml").read_text())
    mpn = parts[params["boards"]["pcb"]]["mpn"]
    m = re.search(r"\brev (\S+)$", mpn)
    return m.group(1) if m else None


def test_catalog_bare_board_entry():
    assert _catalog_revision((ROOT / "hardware" / "bom" / "catalog.yaml").read_text()) == design.REVISION


def test_the_catalog_check_fails_on_a_stale_entry():
    """A broken variant: the catalog as rev B left it."""
    text = (ROOT / "hardware" / "bom" / "catalog.yaml").read_text()
    stale = text.replace(f"robogene-motor-board rev {design.REVISION}", "robogene-motor-board rev A")
    assert _catalog_revision(stale) == "A" != design.REVISION


def test_gerber_job_file_and_gerbers(fab):
    jobs = list((fab / "gerbers").glob("*.gbrjob"))
    assert len(jobs) == 1, jobs
    specs = json.loads(jobs[0].read_text())["GeneralSpecs"]
    assert specs["ProjectId"]["Revision"] == design.REVISION, specs
    for gerber in (fab / "gerbers").glob("*.g[tb]l"):
        project = re.search(r"^%TF\.ProjectId,([^*]*)\*%", gerber.read_text(), re.M).group(1)
        assert project.rsplit(",", 1)[-1] == design.REVISION, (gerber.name, project)
