# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The firmware images `make firmware` put in the fab package: one per board of the head table, each
starting where the STM32G431 boots (stack at the top of its 32 KiB RAM, reset handler in flash), its
settings page where the linker script keeps it, and the size check that refuses an image too big."""
from __future__ import annotations

import re
import struct
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
FAB = ROOT / "build" / "fab" / "firmware"
HEADER = ROOT / "hardware" / "electronics" / "firmware" / "generated" / "robogene_head_board_config.h"
SIZE_REPORT = ROOT / "hardware" / "electronics" / "firmware" / "tools" / "size_report.py"


def boards() -> list[str]:
    return [f"{a}-{n}" for n, a in re.findall(r'^  \{"([a-z0-9-]+)", (\d+)u,', HEADER.read_text(), re.M)]


def symbols(elf: Path) -> dict[str, int]:
    out = subprocess.run(["arm-none-eabi-nm", str(elf)], capture_output=True, text=True, check=True).stdout
    return {parts[2]: int(parts[0], 16) for parts in (l.split() for l in out.splitlines()) if len(parts) == 3}


@pytest.fixture(scope="module", params=boards())
def image(request) -> Path:
    elf = FAB / f"robogene-motor-board-{request.param}.elf"
    if not elf.exists():
        pytest.fail(f"{elf} is missing: run `make firmware` first")
    return elf


def test_every_board_of_the_head_has_its_image_in_every_format():
    assert boards() == ["1-neck-pitch-roll", "2-neck-yaw-eyes-tilt", "3-eyes-pan"]
    for b in boards():
        for ext in ("elf", "hex", "bin", "size.txt"):
            assert (FAB / f"robogene-motor-board-{b}.{ext}").stat().st_size > 0, (b, ext)


def test_the_image_boots_where_the_part_starts(image):
    binary = image.with_suffix(".bin").read_bytes()
    stack, reset = struct.unpack_from("<II", binary, 0)
    syms = symbols(image)
    assert stack == 0x20000000 + 32 * 1024, hex(stack)
    assert reset == syms["rg_reset_handler"] | 1, "the reset vector is the Thumb address of the reset handler"
    assert 0x08000000 <= reset < 0x08000000 + len(binary)
    assert syms["rg_settings_page"] == 0x0801F800, "the last 2 KiB page keeps the settings"
    assert len(binary) < 0x1F800, "the image stays clear of the settings page"
    hex_text = image.with_suffix(".hex").read_text()
    assert hex_text.startswith(":020000040800"), "the HEX file is placed at the flash base"


def test_each_image_runs_its_own_board(image):
    """ROBOGENE_BOARD_ADDRESS differs per image: the address is in the code that picks the table entry."""
    address = int(image.name.split("-")[3])
    out = subprocess.run(["arm-none-eabi-objdump", "-d", "--no-show-raw-insn", str(image)], capture_output=True,
                         text=True, check=True).stdout
    main = out[out.index("<main>:"):]
    main = main[:main.index("\n\n")]
    assert re.search(rf"movs?\s+r0, #{address}\b", main), f"main does not load address {address}"


def test_the_size_report_names_what_does_not_fit(image, tmp_path):
    ok = subprocess.run([sys.executable, str(SIZE_REPORT), str(image), str(tmp_path / "r.txt")], capture_output=True,
                        text=True)
    assert ok.returncode == 0, ok.stderr
    assert "of  129024 bytes" in ok.stdout and "of   32768 bytes" in ok.stdout
    small_flash = subprocess.run([sys.executable, str(SIZE_REPORT), str(image), str(tmp_path / "f.txt"), "--flash", "4096"],
                                 capture_output=True, text=True)
    assert small_flash.returncode == 1
    assert f"{image.name}: flash" in small_flash.stderr and "over the 4096 available" in small_flash.stderr
    assert not (tmp_path / "f.txt").exists()
    small_ram = subprocess.run([sys.executable, str(SIZE_REPORT), str(image), str(tmp_path / "m.txt"), "--ram", "2048"],
                               capture_output=True, text=True)
    assert small_ram.returncode == 1 and "RAM" in small_ram.stderr and "over the 2048 available" in small_ram.stderr
