# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""docs/fabricate.md carries the package's current BOM and mass tables, and its images exist."""
import re

from robogene_head import docs_sync

from conftest import REPO


def test_generated_tables_are_current(fab):
    assert docs_sync.main(["--fab", str(fab), "--check"]) == 0


def test_a_stale_table_is_detected(fab, tmp_path):
    doc = tmp_path / "fabricate.md"
    doc.write_text(docs_sync.DOC.read_text().replace("| mass (kg) |", "| mass (kg, stale) |", 1))
    assert docs_sync.main(["--fab", str(fab), "--doc", str(doc), "--check"]) == 1


def test_images_exist():
    text = (REPO / "docs" / "fabricate.md").read_text()
    images = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", text)
    assert images
    for rel in images:
        assert (REPO / "docs" / rel).stat().st_size > 10000, rel
