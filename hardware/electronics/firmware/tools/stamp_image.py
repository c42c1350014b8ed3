# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Stamps an application image's header with its size and CRC-32, after linking.

The header (core/rg_image.h) sits at 0x200 from the image's start; the compiler wrote its magic,
board, revision and version, and zeros for size and CRC. Size is the length of the flash image
(`objcopy -O binary`), CRC the zlib CRC-32 of those bytes with the CRC field read as zero, which is
what the bootloader computes over the flash. The stamped header replaces the ELF's .image_header
section, so the ELF, HEX and BIN made from it agree. Exit 1, naming the file and what is wrong,
for an image without the header.

usage: stamp_image.py IN.elf OUT.elf [--objcopy arm-none-eabi-objcopy]
"""
from __future__ import annotations

import argparse
import struct
import subprocess
import sys
import tempfile
import zlib
from pathlib import Path

HEADER_OFFSET = 0x200
HEADER_SIZE = 32
MAGIC = 0x4D494752
HEADER_VERSION = 1
SIZE_AT, CRC_AT, VERSION_AT = 4, 8, 12


def image_crc(image: bytes) -> int:
    at = HEADER_OFFSET + CRC_AT
    return zlib.crc32(image[:at] + b"\0\0\0\0" + image[at + 4:])


def stamp(image: bytes, name: str) -> bytes:
    """The header with size and CRC filled in; ValueError naming what is wrong."""
    if len(image) < HEADER_OFFSET + HEADER_SIZE:
        raise ValueError(f"{name}: {len(image)} bytes, too short to hold the image header at 0x{HEADER_OFFSET:X}")
    header = bytearray(image[HEADER_OFFSET:HEADER_OFFSET + HEADER_SIZE])
    magic, size, crc = struct.unpack_from("<III", header, 0)
    if magic != MAGIC or header[VERSION_AT] != HEADER_VERSION:
        raise ValueError(f"{name}: no image header at 0x{HEADER_OFFSET:X} (magic 0x{magic:08X}, "
                         f"header version {header[VERSION_AT]}; expected 0x{MAGIC:08X}, {HEADER_VERSION})")
    if size or crc:
        raise ValueError(f"{name}: the header is stamped already (size {size}, CRC 0x{crc:08X})")
    struct.pack_into("<I", header, SIZE_AT, len(image))
    unstamped = image[:HEADER_OFFSET] + bytes(header) + image[HEADER_OFFSET + HEADER_SIZE:]
    struct.pack_into("<I", header, CRC_AT, image_crc(unstamped))
    return bytes(header)


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("elf", type=Path)
    ap.add_argument("out", type=Path)
    ap.add_argument("--objcopy", default="arm-none-eabi-objcopy")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        binary = Path(tmp) / "image.bin"
        subprocess.run([args.objcopy, "-O", "binary", str(args.elf), str(binary)], check=True)
        try:
            header = stamp(binary.read_bytes(), str(args.elf))
        except ValueError as e:
            print(f"stamp_image: {e}", file=sys.stderr)
            return 1
        section = Path(tmp) / "header.bin"
        section.write_bytes(header)
        subprocess.run([args.objcopy, f"--update-section=.image_header={section}", str(args.elf), str(args.out)],
                       check=True)
    size, crc = struct.unpack_from("<II", header, SIZE_AT)
    print(f"stamp_image: {args.out.name}: {size} bytes, CRC-32 0x{crc:08X}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
