# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The committed type stub runtime/python/robogene/_core.pyi matches the compiled module: it is
regenerated with the pinned pybind11-stubgen and compared, so a binding change without a new
stub (`make python-stub`) fails here. Also: the package is marked typed, and every name the
package exports is in the stub."""
from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import robogene

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "runtime" / "python" / "robogene"


def test_stub_matches_the_compiled_module():
    r = subprocess.run([sys.executable, str(ROOT / "runtime" / "python" / "gen_stub.py"), "--check"],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stdout + r.stderr


def test_every_exported_name_is_in_the_stub():
    tree = ast.parse((PACKAGE / "_core.pyi").read_text())
    stubbed = set()
    for node in tree.body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            stubbed.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            stubbed.add(node.target.id)
        elif isinstance(node, ast.Assign):
            stubbed.update(t.id for t in node.targets if isinstance(t, ast.Name))
    assert set(robogene.__all__) - stubbed == set()
    assert (PACKAGE / "py.typed").exists()
