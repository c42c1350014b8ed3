# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Turns a record_proxy.py log into a fixture: every connection's handshake and messages, with
the payload bytes (hex) and their text rendering, in the format read by tests/python/yarp312.py.

usage: fixtures_from_log.py <log> <title> [most messages a connection] > fixture.txt
Needs the compiled core (robogene.Bottle) for the renderings and to find where a reply ends."""
from __future__ import annotations

import json
import struct
import sys
from collections import defaultdict

from robogene import Bottle

ACK = b"YA\x00\x00\x00\x00RP"
INDEX = b"YA\x0a\x00\x00\x00RP"


def render(payload: bytes) -> str:
    try:
        return Bottle.from_bytes(payload).to_text()
    except Exception:
        return f"<{len(payload)} bytes that are not a Bottle>"


def split_reply(stream: bytes) -> tuple[bytes, bytes]:
    """The reply Bottle at the start of `stream` (everything up to an ACK it parses before), and the rest."""
    at = stream.find(ACK)
    while at >= 0:
        try:
            Bottle.from_bytes(stream[:at])
            return stream[:at], stream[at + len(ACK):]
        except Exception:
            at = stream.find(ACK, at + 1)
    raise ValueError("no reply Bottle followed by an ack")


def binary_messages(c2s: bytes):
    """(command, envelope, payload) of each indexed message after the sender name."""
    pos = 0
    while pos < len(c2s):
        if c2s[pos:pos + 8] != INDEX:
            raise ValueError(f"byte {pos}: not an index header: {c2s[pos:pos + 8].hex()}")
        n_in, n_out = c2s[pos + 8], c2s[pos + 9]
        lengths = struct.unpack(f"<{n_in + n_out}i", c2s[pos + 18:pos + 18 + 4 * (n_in + n_out)])
        pos += 18 + 4 * (n_in + n_out)
        body = c2s[pos:pos + sum(lengths)]
        pos += sum(lengths)
        command, payload, envelope = chr(body[5]), body[8:], ""
        if body[5] == 0:  # a command string: "q", or "d <envelope>" / "D <envelope>"
            (n,) = struct.unpack("<i", body[:4])
            text = payload[:n].rstrip(b"\0").decode()
            payload = payload[n:]
            command, envelope = text[0], text[2:]
        yield command, envelope, payload


def main() -> int:
    log, title = sys.argv[1], sys.argv[2]
    most = int(sys.argv[3]) if len(sys.argv) > 3 else None
    streams = defaultdict(lambda: {"c2s": b"", "s2c": b""})  # in the order the connections began
    for line in open(log):
        entry = json.loads(line)
        streams[entry["conn"]][entry["dir"]] += bytes.fromhex(entry["hex"])
    # REUSE-IgnoreStart
    print("# SPDX-FileCopyrightText: 2026 Robogene contributors")
    print("# SPDX-License-Identifier: BSD-3-Clause")
    # REUSE-IgnoreEnd
    print(f"# {title}")
    print("# Made with record_proxy.py and fixtures_from_log.py (README.md). Lines: `conn <carrier> <sender>`,")
    print("# `> <command> <payload hex> [@ <envelope>]` sent to the server, `< <payload hex>` its reply,")
    print("# `a> <text>` / `a< <text>` admin lines over text_ack; `#` lines render the bytes as YARP text.")
    for conn in streams:
        c2s, s2c = streams[conn]["c2s"], streams[conn]["s2c"]
        head = c2s[:8]
        if head in (b"CONNACK ", b"CONNECT "):
            lines = c2s.decode(errors="replace").split("\r\n")
            print(f"conn text_ack {lines[0][8:]}")
            for request in [l for l in lines[1:] if l and l != "a"]:
                print(f"a> {request}")
            # After "Welcome": each reply line (an empty one too: YARP's answer for a property it lacks).
            for reply in [l for l in s2c.decode(errors="replace").split("\r\n")[1:-1] if l != "<ACK>"]:
                print(f"a< {reply}")
            continue
        carrier = {b"YA\xe4\x1e\x00\x00RP": "tcp", b"YA\x64\x1e\x00\x00RP": "fast_tcp"}.get(head)
        if carrier is None:
            print(f"# conn {conn}: carrier header {head.hex()} not recorded here")
            continue
        (n,) = struct.unpack("<i", c2s[8:12])
        sender = c2s[12:12 + n].rstrip(b"\0").decode()
        print(f"conn {carrier} {sender}")
        rest = s2c[8:]  # the header reply (the server's port number)
        for count, (command, envelope, payload) in enumerate(binary_messages(c2s[12 + n:])):
            if most is not None and count == most:
                print(f"# (the connection's later messages are left out: {most} kept)")
                break
            if command == "q":
                print("> q")
                break
            print(f"# {render(payload)}" + (f"   (envelope {envelope})" if envelope else ""))
            print(f"> {command} {payload.hex()}" + (f" @ {envelope}" if envelope else ""))
            if command == "d":
                reply, rest = split_reply(rest)
                print(f"#   -> {render(reply)}")
                print(f"< {reply.hex()}")
            elif carrier == "tcp":
                rest = rest[len(ACK):]
    return 0


if __name__ == "__main__":
    sys.exit(main())
