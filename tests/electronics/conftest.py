# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Shared paths and a kicad-cli runner with a throwaway HOME (no user library tables leak in)."""
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
BOARD_DIR = ROOT / "hardware" / "electronics" / "motor-board"
NAME = "robogene-motor-board"
SCH = BOARD_DIR / f"{NAME}.kicad_sch"
PCB = BOARD_DIR / f"{NAME}.kicad_pcb"
FAB = pathlib.Path(os.environ.get("ELEC_FAB", ROOT / "build" / "fab" / "electronics"))
GENERATOR = ROOT / "hardware" / "electronics" / "generator"

sys.path.insert(0, str(GENERATOR))
sys.path.insert(0, str(ROOT / "hardware" / "electronics" / "checks"))


@pytest.fixture(scope="session")
def kicad_cli(tmp_path_factory):
    exe = shutil.which("kicad-cli")
    if exe is None:
        pytest.fail("kicad-cli not found: run `make test-electronics` (installs KiCad 9 from bookworm-backports)")
    home = tmp_path_factory.mktemp("kicad-home")
    env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    env["HOME"] = str(home)

    def run(*args, check=True):
        proc = subprocess.run([exe, *map(str, args)], env=env, capture_output=True, text=True, timeout=600)
        if check and proc.returncode != 0:
            pytest.fail(f"kicad-cli {' '.join(map(str, args))} exited {proc.returncode}:\n{proc.stdout}\n{proc.stderr}")
        return proc

    return run


@pytest.fixture(scope="session")
def fab():
    if not (FAB / "pos.csv").exists():
        pytest.fail(f"no fabrication package in {FAB}: run `make electronics` first")
    return FAB
