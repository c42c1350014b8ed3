# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""RPC across implementations: our `rpc` tool against a real YARP RpcServer and a real control
board (yarpdev fakeMotionControl behind controlboardwrapper2)."""
import re

import pytest

from interop_cases import by_name

pytestmark = pytest.mark.timeout(120)

ECHO_CASES = ["capture_sniff_yarp_write", "capture_types", "list_mixed", "int64_min", "blob_bytes",
              "vocab_reply", "float_tenth", "string_nul_escape", "top_ints", "list_float64"]


def responses(proc, count, timeout=15):
    proc.wait_until(f"{count} responses", lambda: sum(l.startswith("Response: ") for l in proc.stdout) >= count,
                    timeout)
    return [l[len("Response: "):] for l in proc.stdout if l.startswith("Response: ")]


def test_robogene_rpc_to_yarp_echo_server(yarpserver, yarp, ours, yarp_bottle_vectors):
    cases = by_name(yarp_bottle_vectors, ECHO_CASES)
    server = yarp.echo_server("/interop/echo")
    client = ours.rpc("/interop/echo")
    for case in cases:
        client.send(case["text"])
    got = responses(client, len(cases))
    assert got == [c["canonical_text"] for c in cases]
    # And YARP read exactly what we meant to send.
    server.wait_until("echo log", lambda: sum(l.startswith("got ") for l in server.stdout) >= len(cases), 5)
    assert [l[4:] for l in server.stdout if l.startswith("got ")] == [c["canonical_text"] for c in cases]


def test_robogene_rpc_to_yarp_fake_control_board(yarpserver, yarp, ours):
    yarp.fake_motors("/interop/motors", joints=4)
    client = ours.rpc("/interop/motors/rpc:i")
    client.send("[get] [axes]")
    client.send("[set] [pos] 1 25.0")
    client.send("[get] [pos] 1")
    client.send("[get] [prot]")
    client.send("[bogus]")
    axes, set_pos, get_pos, prot, bogus = responses(client, 5)
    assert re.fullmatch(r"\[is\] \[axes\] 4 \[tsta\] \d+ \S+ \[ok\]", axes), axes
    assert set_pos == "[ok]"
    assert re.fullmatch(r"\[is\] \[pos\] 25\.0 \[tsta\] \d+ \S+ \[ok\]", get_pos), get_pos
    assert re.fullmatch(r"\[prot\] 1 \d+ \d+ \[ok\]", prot), prot
    assert bogus == "[nak]"
