# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The application images `make firmware` built, flashed over the virtual bus with `robogene can-flash`
into the simulated head (`robogene can-sim --flash-dir`), whose boards run the bootloader's state
machine: the header the Python stamp wrote and the CRC-32 the C bootloader computes must agree, and
each image must be refused by any board but its own."""
from __future__ import annotations

import os
import signal
import subprocess
import time
from pathlib import Path

import pytest

from test_firmware_images import FAB, ROOT, boards

ROBOGENE = ROOT / "build" / "bin" / "robogene"
HEAD_INI = ROOT / "drivers" / "can" / "generated" / "head.ini"


@pytest.fixture(scope="module")
def simulated_head(tmp_path_factory):
    if not ROBOGENE.exists():
        pytest.fail(f"{ROBOGENE} is missing: run `make runtime` first")
    tmp = tmp_path_factory.mktemp("flash")
    env = dict(os.environ, ROBOGENE_CAN_DIR=str(tmp / "bus"))
    (tmp / "bus").mkdir()
    (tmp / "flash").mkdir()
    sim = subprocess.Popen([str(ROBOGENE), "can-sim", "--bus", "virtual:fw", "--from", str(HEAD_INI), "--flash-dir",
                            str(tmp / "flash"), "--duration", "300"], env=env, stdout=subprocess.PIPE, text=True)
    assert "can-sim: 3 boards" in sim.stdout.readline()
    yield env, tmp / "flash"
    sim.send_signal(signal.SIGTERM)
    sim.wait(timeout=10)


def can_flash(env, *args) -> subprocess.CompletedProcess:
    return subprocess.run([str(ROBOGENE), "can-flash", "--bus", "virtual:fw", *args], env=env, capture_output=True,
                          text=True, timeout=120)


@pytest.mark.parametrize("board", boards())
def test_each_built_image_flashes_into_its_own_board(simulated_head, board):
    env, flash = simulated_head
    image = FAB / f"robogene-motor-board-{board}.bin"
    r = can_flash(env, str(image))
    assert r.returncode == 0, r.stdout + r.stderr
    assert f"found board {board.split('-')[0]}," in r.stdout
    assert "verified: CRC-32 0x" in r.stdout and "can-flash: done" in r.stdout
    cells = (flash / f"board-{board}.flash").read_bytes()
    assert cells.startswith(image.read_bytes()), "the simulated flash holds the built image"
    hex_run = can_flash(env, str(image.with_suffix(".hex")))
    assert hex_run.returncode == 0, hex_run.stdout + hex_run.stderr


def test_a_built_image_is_refused_by_another_board(simulated_head):
    env, _ = simulated_head
    r = can_flash(env, "--address", "1", str(FAB / "robogene-motor-board-3-eyes-pan.bin"))
    assert r.returncode == 1
    assert "check:" in r.stderr and "is built for board 3; the board at address 1 is board 1: wrong board" in r.stderr


def test_a_bootloader_image_is_not_taken_for_an_application(simulated_head):
    env, _ = simulated_head
    r = can_flash(env, str(FAB / "robogene-bootloader-3-eyes-pan.bin"))
    assert r.returncode == 1
    assert "no image header at offset 0x200" in r.stderr
