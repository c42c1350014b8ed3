#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the committed seed corpus runtime/fuzz/corpus/<target>/: a few well-formed inputs per
fuzz target (real YARP frames from the captures the tests use, the shapes each decoder expects),
from which libFuzzer mutates. Bottles are encoded with the robogene package, so run it with the
project's venv after `make python`: .venv/bin/python runtime/fuzz/make_seeds.py
The bottle decoders (binary_decoder_fuzz, text_parser_fuzz) are seeded from tests/vectors at run
time instead (run.sh)."""
from __future__ import annotations

import re
import shutil
import struct
import zlib
from pathlib import Path

import robogene

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "runtime" / "fuzz" / "corpus"

# tcp frames of `yarp write /w` -> /r and `yarp rpc` (runtime/carriers/test/carrier/tcp_carrier_test.cpp).
TCP_MESSAGE = ("59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 2e 00 00 00 00 00 00 00 00 00"
               "00 00 7e 44 00 01 00 01 00 00 04 00 00 00 01 00 00 00 01 00 00 00 0a 00 00 00 00 00 00 00"
               "00 00 04 40 04 00 00 00 02 00 00 00 68 69 09 00 00 00 73 65 74 00")
TCP_RPC = ("59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 17 00 00 00 00 00 00 00 00 00"
           "00 00 7e 64 00 01 04 01 00 00 02 00 00 00 03 00 00 00 67 65 74 04 00 00 00 61 78 65 73")
TCP_QUIT = ("59 41 0a 00 00 00 52 50 01 01 ff ff ff ff ff ff ff ff 0a 00 00 00 00 00 00 00 02 00 00 00"
            "7e 00 00 01 71 00")


def hexbytes(text: str) -> bytes:
    return bytes.fromhex(text.replace(" ", ""))


def carrier_index(name: str) -> int:
    # carrier_accept_fuzz picks names()[byte0 % n]: the registry's names, sorted.
    names = sorted(["tcp", "fast_tcp", "text", "text_ack", "udp", "mcast", "shmem", "http"])
    return names.index(name)


def carrier_accept() -> dict[str, bytes]:
    well_formed, raw = 1, 0
    seeds = {}
    for name in ("tcp", "fast_tcp"):
        seeds[f"{name}-message-quit"] = bytes([carrier_index(name), well_formed]) + hexbytes(TCP_MESSAGE + TCP_QUIT)
        seeds[f"{name}-rpc"] = bytes([carrier_index(name), well_formed]) + hexbytes(TCP_RPC)
    for name in ("text", "text_ack"):
        seeds[f"{name}-commands"] = bytes([carrier_index(name), well_formed]) + (
            b"d\r\n1 2 \"three\" [set] (4 5.5)\r\na\r\n[list] [in]\r\n*\r\n/elsewhere\r\n?\r\nq\r\n")
    seeds["http-get-data"] = bytes([carrier_index("http"), raw]) + b"data=1+2 HTTP/1.1\r\nHost: x\r\n\r\n"
    seeds["http-post-form"] = bytes([carrier_index("http"), raw]) + (
        b"m HTTP/1.1\r\nContent-Type: application/x-www-form-urlencoded\r\nContent-Length: 10\r\n\r\ndata=1+2+3")
    for name in ("udp", "mcast", "shmem"):
        seeds[f"{name}-handshake"] = bytes([carrier_index(name), well_formed])
    return seeds


def datagram_records(flags: int, datagrams: list[tuple[int, int, bytes]]) -> bytes:
    """Input of udp/mcast_datagram_fuzz (datagram_fuzz_harness.hpp): flags, then per datagram
    `ctl, len (big-endian), [crc], [counter], body`; crc and counter only where the flags leave
    them to the input. Each datagram is (ctl, counter, body)."""
    out = bytearray([flags])
    for ctl, counter, body in datagrams:
        out += bytes([ctl]) + struct.pack(">H", len(body))
        if not flags & 1:
            out += struct.pack("<I", zlib.crc32(body))  # the CRC covers what follows the prefix
        if not flags & 2:
            out += struct.pack("<i", counter)
        out += body
    return bytes(out)


def datagram() -> dict[str, bytes]:
    # The tcp frames again: a udp or mcast writer sends the same index + PortCommand + payload,
    # cut into datagrams each prefixed `crc32(rest), counter` (reference 3.6).
    message, rpc, quit_ = hexbytes(TCP_MESSAGE), hexbytes(TCP_RPC), hexbytes(TCP_QUIT)
    fixed, numbered, first = 1, 2, 1
    third = len(message) // 3
    return {
        "message-one-datagram": datagram_records(fixed | numbered, [(first, 0, message)]),
        "message-three-datagrams": datagram_records(fixed | numbered, [
            (first, 0, message[:third]), (0, 1, message[third:2 * third]), (0, 2, message[2 * third:])]),
        "rpc-then-quit": datagram_records(fixed | numbered, [(first, 0, rpc), (first, 0, quit_)]),
        # counters given by the input: the middle datagram of the message is missing
        "message-lost-datagram": datagram_records(fixed, [
            (0, 0, message[:third]), (0, 2, message[2 * third:]), (0, 0, rpc)]),
        # everything given by the input, as it would be on the wire
        "message-raw-prefix": datagram_records(0, [(0, 0, message), (0, 0, rpc)]),
    }


def name_service() -> dict[str, bytes]:
    return {
        "session": b"register /w\nset /w offers tcp text\nquery /w\nbot list\nget /w offers\nunregister /w\nquery /w\n",
        "explicit": b"NAME_SERVER register /r tcp 127.0.0.1 10005\nNAME_SERVER check /r offers tcp\nroute /w /r\n",
        "mcast": b"register /m mcast ... ...\nannounce /m\nrunners\ngc\nhelp\n",
    }


def name_server_wire() -> dict[str, bytes]:
    # What yarp tools send /root: name_ser lines, text and text_ack sessions, a browser.
    return {
        "name_ser": b"NAME_SERVER query /root\r\n",
        "text": b"CONNECT /fuzz\r\nd\r\nregister /w\r\nd\r\nquery /w\r\n*\r\na\r\n[list] [in]\r\nq\r\n",
        "text_ack": b"CONNACK foo\r\nd\r\nbot list\r\n",
        "tcp": hexbytes("59 41 e4 1e 00 00 52 50 03 00 00 00 2f 77 00") + hexbytes(TCP_RPC) + hexbytes(TCP_QUIT),
        "http": b"GET /bot/query/%2Froot?format=json HTTP/1.1\r\n\r\n",
    }


def http_request() -> dict[str, bytes]:
    return {"data": b"data=1+2+%22a+b%22", "call": b"get/axes?format=json", "req": b"?req=get+pos+1.5",
            "lines": b"d%0A1+2%0A*"}


def bottle(text: str) -> bytes:
    return robogene.Bottle.from_text(text).to_bytes()


def device_rpc() -> dict[str, bytes]:
    seeds = {}
    for i, text in enumerate(["get axes", "[get] [axes]", "[set] [pos] 0 30.5", "[get] [encs]", "[set] [vmos] (1 2 3 4)",
                              "[get] [pid] [pos] 1", "help", "[set] [icmd] [cmod] 0 [vel]"]):
        seeds[f"controlboard-{i}"] = b"\x00" + bottle(text)
    seeds["command"] = b"\x01" + bottle("(0 1) (10.0 20.0)")
    for i, text in enumerate(["[get] [w]", "[get] [h]", "help"]):
        seeds[f"grabber-{i}"] = b"\x02" + bottle(text)
    return seeds


def joint_data() -> dict[str, bytes]:
    header = (ROOT / "runtime" / "test" / "dev" / "captured_joint_data.hpp").read_text()
    captured = "".join(re.findall(r'"([0-9a-f]+)"', header.split("kCapturedJointData", 1)[1].split(";", 1)[0]))
    return {"yarp-captured": bytes.fromhex(captured)}


def image_codec() -> dict[str, bytes]:
    pixels = " ".join(str(i) for i in range(16))
    return {"2x2-quantum8-bottom-up": bottle(f"[mat] [rgb] (3 16 65544 2 2) {{{pixels}}}"),
            "1x1-quantum1": bottle("[mat] [rgb] (3 3 1 1 1) {255 0 7}")}


def can_frame() -> dict[str, bytes]:
    return {
        # even first byte: a frame (id low, id high, length, data)
        "frame-0x201": bytes([0, 0x01, 0x02, 4, 20, 0, 0, 0]),
        "frame-0x10f": bytes([0, 0x0F, 0x01, 8, 1, 2, 3, 4, 5, 6, 7, 8]),
        # odd first byte: a candump log line
        "log-line": b"\x01(1700000000.000001) vcan0 201#1400",
        "log-error": b"\x01(1700000000.5) can0 20000004#0004000000000000",
    }


def main() -> None:
    targets = {"carrier_accept_fuzz": carrier_accept(), "name_service_fuzz": name_service(),
               "name_server_wire_fuzz": name_server_wire(),
               "http_request_fuzz": http_request(), "device_rpc_fuzz": device_rpc(), "joint_data_fuzz": joint_data(),
               "image_codec_fuzz": image_codec(), "can_frame_fuzz": can_frame(),
               "udp_datagram_fuzz": datagram(), "mcast_datagram_fuzz": datagram()}
    for target, seeds in targets.items():
        folder = OUT / target
        if folder.exists():
            for old in folder.glob("seed-*"):
                old.unlink()  # regression inputs (crash-*) stay
        folder.mkdir(parents=True, exist_ok=True)
        for name, data in seeds.items():
            (folder / f"seed-{name}").write_bytes(data)


if __name__ == "__main__":
    main()
