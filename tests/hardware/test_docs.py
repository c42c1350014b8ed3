# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""docs/fabricate.md carries the package's current BOM and mass tables (the manifest's
`fabrication-tables` generator, checked by the same driver as `make check-generated`), and its images exist."""
import os
import re
import shutil
import subprocess
import sys

from conftest import REPO

TABLES = "hardware/mechanics/robogene_head/docs_sync.py"


def codegen(root, fab, command="check"):
    return subprocess.run([sys.executable, "-m", "robogene_codegen", command, "--root", str(root),
                           "--only", "fabrication-tables", "--fab", str(fab)],
                          env=dict(os.environ, PYTHONPATH=str(REPO / "codegen")), capture_output=True, text=True)


def test_generated_tables_are_current(fab):
    result = codegen(REPO, fab)
    assert result.returncode == 0, result.stderr


def test_a_stale_table_is_detected_and_regenerated(fab, tmp_path):
    for rel in ("codegen/generated-manifest.yaml", "docs/fabricate.md", TABLES):
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(REPO / rel, tmp_path / rel)
    doc = tmp_path / "docs" / "fabricate.md"
    doc.write_text(doc.read_text().replace("| mass (kg) |", "| mass (kg, stale) |", 1))
    result = codegen(tmp_path, fab)
    assert result.returncode == 1 and "stale: docs/fabricate.md: differs" in result.stderr, result.stderr
    assert codegen(tmp_path, fab, "generate").returncode == 0
    assert doc.read_text() == (REPO / "docs" / "fabricate.md").read_text()


def test_images_exist():
    text = (REPO / "docs" / "fabricate.md").read_text()
    images = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", text)
    assert images
    for rel in images:
        assert (REPO / "docs" / rel).stat().st_size > 10000, rel
