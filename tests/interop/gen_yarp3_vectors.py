#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Regenerate tests/vectors/yarp3_bottles.json and yarp3_typed_values.json from the real YARP peer.

Run with the peer's interpreter:  .yarp-venv/bin/python tests/interop/gen_yarp3_vectors.py [OUT_DIR]
(OUT_DIR defaults to tests/vectors; the interop tests write elsewhere and compare.)
For each text: Bottle.fromString (YARP's parser), Bottle.toString (YARP's rendering), and the bytes a
yarp.Port writes for it, captured by a raw-socket input port on a private yarpserver. Values the text
syntax cannot express (int8, int16, float32) are built with the typed add* calls instead.
The JSON files are facts about YARP: they change only when this script is rerun on purpose."""
from __future__ import annotations

import json
import os
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import interop_net  # noqa: E402
from interop_peer import ROOT, PrivateNetwork, yarp_tool  # noqa: E402
from interop_procs import ProcessGroup  # noqa: E402
from yarp3_vector_cases import CASES  # noqa: E402
from yarp_sniffer import Sniffer  # noqa: E402

DATA_COMMAND = b"\x00\x00\x00\x00~D\x00\x01"   # PortCommand 'D': data, no reply


def typed_cases():
    """(name, builder) for values only the typed API can make."""
    def one(method, *args):
        def build(b):
            getattr(b, method)(*args)
        return build

    def several(*calls):
        def build(b):
            for method, *args in calls:
                getattr(b, method)(*args)
        return build

    def nested(*calls):
        def build(b):
            inner = b.addList()
            for method, *args in calls:
                getattr(inner, method)(*args)
        return build

    return [
        ("int8_five", one("addInt8", 5)),
        ("int8_min", one("addInt8", -128)),
        ("int8_max", one("addInt8", 127)),
        ("int16_min", one("addInt16", -32768)),
        ("int16_max", one("addInt16", 32767)),
        ("int32_via_api", one("addInt32", 7)),
        ("int64_small_via_api", one("addInt64", 7)),
        ("float32_half", one("addFloat32", 0.5)),
        ("float32_tenth", one("addFloat32", 0.1)),
        ("float32_integral", one("addFloat32", 3.0)),
        ("float64_integral_via_api", one("addFloat64", 3.0)),
        ("vocab32_via_api", one("addVocab32", "abcd")),
        ("string_via_api_with_nul", one("addString", "a\0b")),
        ("int8_list", several(("addInt8", 1), ("addInt8", 2), ("addInt8", 3))),
        ("int16_list", several(("addInt16", 1), ("addInt16", -2))),
        ("float32_list", several(("addFloat32", 1.5), ("addFloat32", -2.5))),
        ("int8_int16_mixed", several(("addInt8", 1), ("addInt16", 1))),
        ("nested_int8_list", nested(("addInt8", 9), ("addInt8", 10))),
        ("nested_float32_list", nested(("addFloat32", 0.25))),
        ("int64_list_via_api", several(("addInt64", 1), ("addInt64", 2))),
    ]


def capture(port, sniffer, bottle) -> str:
    port.write(bottle)
    msg = sniffer.next()
    if msg.command != DATA_COMMAND:
        raise RuntimeError(f"unexpected PortCommand {msg.command!r} for {bottle.toString()!r}")
    return msg.payload.hex()


def main() -> int:
    out_dir = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "tests" / "vectors"
    procs = ProcessGroup()
    with tempfile.TemporaryDirectory(prefix="yarp-vectors-") as tmp:
        net = PrivateNetwork.create(Path(tmp), interop_net.free_port_block())
        os.environ.clear()
        os.environ.update(net.env)
        try:
            procs.start("yarpserver", [yarp_tool("yarpserver"), "--ip", "127.0.0.1", "--socket", str(net.ns_port),
                                       "--read", "--portdb", ":memory:", "--subdb", ":memory:"], net.env, cwd=tmp)
            interop_net.wait_registered(net.ns_port, "/root", 15)
            sniffer = Sniffer()
            reply = interop_net.name_server_request(net.ns_port, f"register /interop_sniff tcp 127.0.0.1 {sniffer.port}")
            if "registration name /interop_sniff" not in reply:
                raise RuntimeError(f"registering the sniffer failed: {reply!r}")

            import yarp
            yarp.Network.init()
            version = yarp.YARP_VERSION_SHORT  # the PyPI 3.5.0 sdist calls itself "3.5.0~dev" in YARP_VERSION
            port = yarp.Port()
            if not port.open("/interop_vectors"):
                raise RuntimeError("cannot open /interop_vectors")
            if not yarp.Network.connect("/interop_vectors", "/interop_sniff"):
                raise RuntimeError("yarp.Network.connect to the sniffer failed")
            source = f"yarp {version} Bottle.fromString/toString, bytes captured from yarp.Port.write over tcp"

            bottles = []
            for name, text in CASES:
                b = yarp.Bottle()
                b.fromString(text)
                bottles.append({"name": name, "text": text, "canonical_text": b.toString(),
                                "hex": capture(port, sniffer, b), "source": source})

            typed_source = f"yarp {version} Bottle typed add* calls/toString, bytes captured from yarp.Port.write over tcp"
            typed = []
            for name, build in typed_cases():
                b = yarp.Bottle()
                build(b)
                typed.append({"name": name, "canonical_text": b.toString(),
                              "hex": capture(port, sniffer, b), "source": typed_source})
            port.close()
            yarp.Network.fini()
        finally:
            procs.stop_all()

    for fname, data in (("yarp3_bottles.json", bottles), ("yarp3_typed_values.json", typed)):
        (out_dir / fname).write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n")
        print(f"wrote {len(data)} vectors to {out_dir / fname}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
