# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Shared fixtures for the head's hardware tests. The package tests read build/fab (built by `make fab`,
which `make test-hardware` depends on); the geometry tests rebuild what they check from the parameters, the
board STEP the package was built with and a face plate rendered here by OpenSCAD."""
import json
import os
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path[:0] = [str(REPO / "hardware" / "mechanics"), str(REPO / "hardware" / "bom")]
os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")

FAB = Path(os.environ.get("ROBOGENE_FAB", REPO / "build" / "fab"))
DATA = Path(__file__).resolve().parent / "data"


@pytest.fixture(scope="session")
def params():
    from robogene_head_model import params as p
    return p.load()


@pytest.fixture(scope="session")
def fab():
    if not (FAB / "manifest.json").exists():
        pytest.fail(f"{FAB} has no manifest.json: build the package first (make fab)")
    return FAB


@pytest.fixture(scope="session")
def board_step(fab):
    """The KiCad board STEP the package was built with (make passes build/fab/electronics/board.step)."""
    return Path(json.loads((fab / "manifest.json").read_text())["board_step"]["path"])


@pytest.fixture(scope="session")
def external(params, board_step, tmp_path_factory):
    from robogene_head import external as ext
    return ext.render_and_load(params, board_step, tmp_path_factory.mktemp("scad"))


@pytest.fixture(scope="session")
def assembly(params, external):
    from robogene_head.assembly import Assembly
    return Assembly(params, external=external)
