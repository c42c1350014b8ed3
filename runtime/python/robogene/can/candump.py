# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Decode a candump log with the head's protocol: one text-form line per frame.

    python -m robogene.can.candump session.log        # or: candump -L can0 | python -m robogene.can.candump

Reads candump's log form `(1795392000.001000) can0 001#1BE80300001900` and its compact form
`001#1BE80300001900`. A line that is not a frame, or a frame the protocol does not know, is reported
on stderr as `<file>:<line>: <what>`; the exit code is 1 when there was any.
"""
from __future__ import annotations

import argparse
import re
import sys
from typing import Iterable, Iterator, NamedTuple, Optional, TextIO

from .generated.motor_control import CodecError, Frame, decode, to_text

_LINE = re.compile(r"\s*(?:\((?P<time>\d+\.\d+)\)\s+(?P<iface>\S+)\s+)?(?P<id>[0-9A-Fa-f]{1,3})#(?P<data>[0-9A-Fa-f]*)\s*")


class LogEntry(NamedTuple):
    timestamp: Optional[float]
    interface: Optional[str]
    frame: Frame


def parse_line(line: str) -> LogEntry:
    """One candump line; raises ValueError saying what is wrong with it."""
    m = _LINE.fullmatch(line)
    if not m:
        raise ValueError(f"not a candump frame of an 11-bit identifier: {line.strip()!r}")
    data = m.group("data")
    if len(data) % 2 or len(data) > 16:
        raise ValueError(f"data '{data}' is not 0 to 8 bytes of hex")
    timestamp = float(m.group("time")) if m.group("time") else None
    return LogEntry(timestamp, m.group("iface"), Frame(int(m.group("id"), 16), bytes.fromhex(data)))


def read_log(lines: Iterable[str]) -> Iterator[tuple[int, LogEntry]]:
    """(line number, entry) of every frame; blank lines are skipped, bad ones raise ValueError
    with the line number."""
    for number, line in enumerate(lines, 1):
        if line.strip():
            try:
                yield number, parse_line(line)
            except ValueError as exc:
                raise ValueError(f"line {number}: {exc}") from None


def decode_log(stream: TextIO, out: TextIO, err: TextIO, name: str) -> int:
    problems = 0
    for number, line in enumerate(stream, 1):
        if not line.strip():
            continue
        try:
            entry = parse_line(line)
            text = to_text(decode(entry.frame))
        except (ValueError, CodecError) as exc:
            print(f"{name}:{number}: {exc}", file=err)
            problems += 1
            continue
        stamp = f"({entry.timestamp:.6f}) " if entry.timestamp is not None else ""
        iface = f"{entry.interface} " if entry.interface else ""
        print(f"{stamp}{iface}{entry.frame}  {text}", file=out)
    return 1 if problems else 0


def main(argv: Optional[list[str]] = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m robogene.can.candump", description=__doc__.split("\n")[0])
    parser.add_argument("log", nargs="?", help="candump log file (default: standard input)")
    args = parser.parse_args(argv)
    if args.log is None:
        return decode_log(sys.stdin, sys.stdout, sys.stderr, "<stdin>")
    try:
        with open(args.log, encoding="utf-8") as stream:
            return decode_log(stream, sys.stdout, sys.stderr, args.log)
    except OSError as exc:
        print(f"{args.log}: cannot read: {exc.strerror}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
