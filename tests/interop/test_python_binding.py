# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The Python binding (robogene, imported by this test process) against real YARP 3 on a real
`yarpserver`: `yarp rpc` to a Python RpcServer, a Python RpcClient to a YARP RpcServer,
`yarp write` to a Python BufferedPort and a Python Port to `yarp read`."""
import pytest

import robogene
from interop_cases import by_name

pytestmark = pytest.mark.timeout(120)

CASES = ["capture_types", "list_mixed", "int64_min", "blob_bytes", "vocab_reply", "float_tenth", "list_float64"]


@pytest.fixture
def names(yarpserver, net):
    """The binding's client of the YARP name server (found through its address)."""
    return robogene.Network(net.server_arg)


def responses(proc, count, timeout=15):
    proc.wait_until(f"{count} responses", lambda: sum(l.startswith("Response: ") for l in proc.stdout) >= count,
                    timeout)
    return [l[len("Response: "):] for l in proc.stdout if l.startswith("Response: ")]


def test_yarp_rpc_to_python_rpc_server(names, yarp, yarp_bottle_vectors):
    cases = by_name(yarp_bottle_vectors, CASES)
    senders = []

    def echo(request, info):
        senders.append(info.sender)
        return request
    with robogene.RpcServer("/interop/py/rpc:i", echo, network=names) as server:
        assert names.query("/interop/py/rpc:i") == server.contact
        client = yarp.rpc("/interop/py/rpc:i")
        for case in cases:
            client.send(case["text"])
        assert responses(client, len(cases)) == [c["canonical_text"] for c in cases]
        client.close_stdin()
    assert set(senders) == {senders[0]} and senders[0] != "/interop/py/rpc:i"
    assert names.query("/interop/py/rpc:i") is None, "closing unregistered it from yarpserver"


def test_python_rpc_client_to_yarp_rpc_server(names, yarp, yarp_bottle_vectors):
    cases = by_name(yarp_bottle_vectors, CASES)
    server = yarp.echo_server("/interop/echo")
    with robogene.RpcClient("/interop/py/rpc:o", server="/interop/echo", network=names) as client:
        for case in cases:
            request = robogene.Bottle.from_text(case["text"])
            reply = client.call(request)
            assert reply.to_text() == case["canonical_text"]
            assert reply.to_bytes().hex() == case["hex"], case["name"]
    server.wait_until("echo log", lambda: sum(l.startswith("got ") for l in server.stdout) >= len(cases), 5)
    assert [l[4:] for l in server.stdout if l.startswith("got ")] == [c["canonical_text"] for c in cases]


def test_yarp_write_to_python_buffered_port(names, yarp):
    with robogene.BufferedPort("/interop/py/in", policy="strict", network=names) as reader:
        writer = yarp.write("/interop/yw", "/interop/py/in")
        writer.send('1 2.5 "hi" [set]')
        got, info = reader.read_with_info(timeout=15)
        assert got.to_text() == '1 2.5 hi [set]' and info.sender == "/interop/yw"
        writer.close_stdin()


def test_python_port_to_yarp_read(names, yarp):
    reader = yarp.read("/interop/yr")
    with robogene.Port("/interop/py/out", network=names) as writer:
        writer.add_output("/interop/yr")
        assert writer.write(robogene.Bottle.from_text('(nested 1 2) {1 2 255} 0.5'))
        assert reader.wait_data(1, 15)[-1] == "(nested 1 2) {1 2 255} 0.5"
