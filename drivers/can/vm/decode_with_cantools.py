#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Decodes candump logs of a head session with cantools and the generated DBC: every frame must be
a message the DBC knows and decode without error. Run by `make test-can-vm` on the logs the VM
wrote (can-utils' candump recording of vcan0, and the simulator's and driver's own logs), so a
session over real SocketCAN is read by a third-party tool.

Usage: decode_with_cantools.py HEAD.dbc LOG...   (exit 0: every frame decoded)"""
import collections
import sys

import cantools
from cantools.logreader import Parser


def decode_log(db, path: str) -> collections.Counter:
    seen = collections.Counter()
    parser = Parser()
    with open(path, encoding="ascii") as f:
        for number, line in enumerate(f, start=1):
            if not line.strip():
                continue
            entry = parser.parse(line.rstrip("\n"))
            if entry is None:
                raise ValueError(f"{path}:{number}: cantools cannot parse this line: {line.strip()!r}")
            try:
                message = db.get_message_by_frame_id(entry.frame_id)
                # The DBC gives each multiplexed message its longest layout; shorter commands are truncated.
                message.decode(bytes(entry.data), allow_truncated=True)
            except (KeyError, cantools.database.DecodeError) as e:
                raise ValueError(f"{path}:{number}: frame {entry.frame_id:03X}#{bytes(entry.data).hex().upper()}: {e}") from e
            seen[message.name] += 1
    return seen


def main(argv: list[str]) -> int:
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    db = cantools.database.load_file(argv[0])
    failed = 0
    for path in argv[1:]:
        try:
            seen = decode_log(db, path)
        except (OSError, ValueError) as e:
            print(f"FAIL {e}")
            failed += 1
            continue
        frames = sum(seen.values())
        if frames < 100:
            print(f"FAIL {path}: only {frames} frames, too few for a head session")
            failed += 1
            continue
        print(f"ok   {path}: {frames} frames decoded by cantools, {len(seen)} kinds of message")
    print(f"{len(argv) - 1 - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
