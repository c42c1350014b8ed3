# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The firmware images `make firmware` put in the fab package: per board of the head table, an
application linked after the bootloader (stack at the top of its 32 KiB RAM, reset handler in its
own region, its image header stamped) and a bootloader where the STM32G431 boots; the settings
page where both linker scripts keep it, and the size check that refuses an image too big."""
from __future__ import annotations

import re
import struct
import subprocess
import sys
import zlib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
FAB = ROOT / "build" / "fab" / "firmware"
HEADER = ROOT / "hardware" / "electronics" / "firmware" / "generated" / "robogene_head_board_config.h"
SIZE_REPORT = ROOT / "hardware" / "electronics" / "firmware" / "tools" / "size_report.py"
STAMP = ROOT / "hardware" / "electronics" / "firmware" / "tools" / "stamp_image.py"


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


APP_BASE = 0x08004000
BOOT_BASE = 0x08000000


def test_every_board_of_the_head_has_its_images_in_every_format():
    assert boards() == ["1-neck-pitch-roll", "2-neck-yaw-eyes-tilt", "3-eyes-pan"]
    for b in boards():
        for kind in ("motor-board", "bootloader"):
            for ext in ("elf", "hex", "bin", "size.txt"):
                assert (FAB / f"robogene-{kind}-{b}.{ext}").stat().st_size > 0, (kind, b, ext)


def test_the_application_starts_after_the_bootloader(image):
    binary = image.with_suffix(".bin").read_bytes()
    stack, reset = struct.unpack_from("<II", binary, 0)
    syms = symbols(image)
    assert stack == 0x20000000 + 32 * 1024, hex(stack)
    assert reset == syms["rg_reset_handler"] | 1, "the reset vector is the Thumb address of the reset handler"
    assert syms["vectors"] == APP_BASE, "the vector table opens the application region"
    assert APP_BASE <= reset < APP_BASE + len(binary)
    assert syms["rg_settings_page"] == 0x0801F800, "the last 2 KiB page keeps the settings"
    assert APP_BASE + len(binary) <= 0x0801F800, "the image stays clear of the settings page"
    assert syms["rg_boot_handoff"] == 0x20000000 and syms["_data_start"] >= 0x20000010, \
        "the handoff words stay out of .data and .bss"
    hex_text = image.with_suffix(".hex").read_text()
    assert hex_text.startswith(":020000040800F2\n:10400000"), "the HEX file is placed at the application's base"


def test_the_bootloader_boots_where_the_part_starts(image):
    boot = image.with_name(image.name.replace("motor-board", "bootloader"))
    binary = boot.with_suffix(".bin").read_bytes()
    stack, reset = struct.unpack_from("<II", binary, 0)
    syms = symbols(boot)
    assert stack == 0x20000000 + 32 * 1024, hex(stack)
    assert reset == syms["rg_reset_handler"] | 1
    assert BOOT_BASE <= reset < BOOT_BASE + len(binary)
    assert len(binary) <= 16 * 1024, "the bootloader fits its 16 KiB"
    assert syms["rg_app_region"] == APP_BASE and syms["rg_app_region_size"] == 110 * 1024
    assert syms["rg_settings_page"] == 0x0801F800 and syms["rg_boot_handoff"] == 0x20000000
    assert boot.with_suffix(".hex").read_text().startswith(":020000040800F2\n:10000000")


def test_the_application_image_header_is_stamped_with_its_size_and_crc(image):
    """What the bootloader checks before it starts an image: the header the build wrote."""
    binary = image.with_suffix(".bin").read_bytes()
    magic, size, crc = struct.unpack_from("<III", binary, 0x200)
    header_version, board_type, board_id, revision = binary[0x20C:0x210]
    assert magic == 0x4D494752 and header_version == 1
    assert size == len(binary)
    assert crc == zlib.crc32(binary[:0x208] + bytes(4) + binary[0x20C:])
    assert board_type == 200 and board_id == int(image.name.split("-")[3])
    design = (ROOT / "hardware" / "electronics" / "generator" / "design.py").read_text()
    assert chr(revision) == re.search(r'^REVISION = "([A-Z])"', design, re.M).group(1)
    elf_header = subprocess.run(["arm-none-eabi-objcopy", "-O", "binary", "--only-section=.image_header", str(image),
                                 "/dev/stdout"], capture_output=True, check=True).stdout
    assert elf_header == binary[0x200:0x220], "the ELF carries the stamped header too (SWD flashes the ELF)"


def test_the_stamp_refuses_an_image_without_a_header_and_one_stamped_twice(image, tmp_path):
    sys.path.insert(0, str(STAMP.parent))
    import stamp_image
    binary = image.with_suffix(".bin").read_bytes()
    unstamped = binary[:0x204] + bytes(8) + binary[0x20C:]
    header = stamp_image.stamp(unstamped, "x.elf")
    assert header == binary[0x200:0x220], "stamping the unstamped image again gives the same header"
    with pytest.raises(ValueError, match="is stamped already"):
        stamp_image.stamp(binary, "x.elf")
    broken = bytearray(unstamped)
    broken[0x200] ^= 0xFF
    with pytest.raises(ValueError, match="x.elf: no image header at 0x200"):
        stamp_image.stamp(bytes(broken), "x.elf")
    with pytest.raises(ValueError, match="too short"):
        stamp_image.stamp(unstamped[:0x210], "x.elf")


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
    assert "of  112640 bytes" in ok.stdout and "of   32768 bytes" in ok.stdout
    small_flash = subprocess.run([sys.executable, str(SIZE_REPORT), str(image), str(tmp_path / "f.txt"), "--flash", "4096"],
                                 capture_output=True, text=True)
    assert small_flash.returncode == 1
    assert f"{image.name}: flash" in small_flash.stderr and "over the 4096 available" in small_flash.stderr
    assert not (tmp_path / "f.txt").exists()
    small_ram = subprocess.run([sys.executable, str(SIZE_REPORT), str(image), str(tmp_path / "m.txt"), "--ram", "2048"],
                               capture_output=True, text=True)
    assert small_ram.returncode == 1 and "RAM" in small_ram.stderr and "over the 2048 available" in small_ram.stderr


def test_the_bootloader_checks_the_image_before_it_jumps_with_the_applications_table(image):
    """main() of each bootloader: the handoff request, the image check, then VTOR, MSP and a branch
    to the reset vector, all read from the application region's first two words."""
    boot = image.with_name(image.name.replace("motor-board", "bootloader"))
    out = subprocess.run(["arm-none-eabi-objdump", "-d", "--no-show-raw-insn", str(boot)], capture_output=True,
                         text=True, check=True).stdout
    main = out[out.index("<main>:"):]
    main = main[:main.index("\n\n")]
    calls = re.findall(r"bl\s+\w+ <(\w+)>", main)
    assert calls.index("handoff_take_bootloader_request") < calls.index("rg_boot_image_valid") < calls.index("fdcan_init")
    jump = main[main.index("<rg_boot_image_valid>"):main.index("<fdcan_init>")]
    assert re.search(r"str(\.w)?\s+r\d+, \[r\d+, #3336\]", jump), "VTOR (0xE000ED08) is set"
    assert re.search(r"msr\s+MSP, r\d+", jump) and re.search(r"\bbx\s+r\d+", jump), "stack pointer, then the reset vector"
