# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Checks a firmware image against the STM32G431KB's memory and writes its size report.

Flash holds the vector table, code, read-only data and the initial values of .data; RAM holds
.data, .bss and the stack the linker script reserves (.stack_check). Limits: the application's
region, 110 KiB of the 128 KiB flash (the bootloader keeps 16 KiB, the settings 2 KiB; the
bootloader's own report passes --flash 16384), and 32 KiB RAM. Exit 1, naming the image and the memory, when either is over.

usage: size_report.py IMAGE.elf REPORT.txt [--size arm-none-eabi-size] [--flash BYTES] [--ram BYTES]
"""
from __future__ import annotations

import argparse
import subprocess
import sys
from pathlib import Path

FLASH_BYTES = 110 * 1024
RAM_BYTES = 32 * 1024
FLASH_SECTIONS = (".vectors", ".image_header", ".text", ".ARM.exidx", ".data")
RAM_SECTIONS = (".data", ".bss", ".stack_check")


def sections(size_tool: str, elf: Path) -> dict[str, int]:
    out = subprocess.run([size_tool, "-A", "-d", str(elf)], capture_output=True, text=True, check=True).stdout
    found = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[0].startswith(".") and parts[1].isdigit():
            found[parts[0]] = int(parts[1])
    return found


def report(elf: Path, found: dict[str, int], flash_limit: int, ram_limit: int) -> tuple[str, list[str]]:
    if ".text" not in found or ".vectors" not in found:
        return "", [f"{elf.name}: no .vectors/.text section: not a firmware image"]
    flash = sum(found.get(s, 0) for s in FLASH_SECTIONS)
    ram = sum(found.get(s, 0) for s in RAM_SECTIONS)
    lines = [f"{elf.name}: STM32G431KB",
             f"  flash {flash:7d} of {flash_limit:7d} bytes ({100.0 * flash / flash_limit:5.1f} %)",
             f"  RAM   {ram:7d} of {ram_limit:7d} bytes ({100.0 * ram / ram_limit:5.1f} %), stack reserve included",
             "  " + ", ".join(f"{s} {found[s]}" for s in FLASH_SECTIONS + RAM_SECTIONS[1:] if s in found)]
    problems = []
    if flash > flash_limit:
        problems.append(f"{elf.name}: flash {flash} bytes is over the {flash_limit} available")
    if ram > ram_limit:
        problems.append(f"{elf.name}: RAM {ram} bytes is over the {ram_limit} available")
    return "\n".join(lines) + "\n", problems


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("elf", type=Path)
    ap.add_argument("report", type=Path)
    ap.add_argument("--size", default="arm-none-eabi-size")
    ap.add_argument("--flash", type=int, default=FLASH_BYTES)
    ap.add_argument("--ram", type=int, default=RAM_BYTES)
    args = ap.parse_args(argv)
    text, problems = report(args.elf, sections(args.size, args.elf), args.flash, args.ram)
    for p in problems:
        print(f"size_report: {p}", file=sys.stderr)
    if problems:
        return 1
    args.report.write_text(text)
    sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
