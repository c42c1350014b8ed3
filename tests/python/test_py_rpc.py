# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""robogene.RpcClient and robogene.RpcServer from Python: handlers and what they may return,
read()/reply(), a handler that raises, and the errors of a client with no server."""
from __future__ import annotations

import sys
import threading

import pytest

import robogene

pytestmark = pytest.mark.timeout(60)


def test_handler_answers_and_learns_the_sender(network):
    def handler(request, info):
        return [request[0].as_int() * 2, info.sender, info.reply_expected]
    with robogene.RpcServer("/py/calc", handler, network=network):
        with robogene.RpcClient(server="/py/calc", network=network) as anon:
            assert anon.call([21]).to_text() == "42 anon_rpc true"
        with robogene.RpcClient("/py/named", server="/py/calc", network=network) as named:
            assert named.call(robogene.Bottle([5])).to_text() == '10 "/py/named" true'
            assert named.outputs == ["/py/calc"]


@pytest.mark.parametrize("answer, text", [
    (None, ""),
    ((1, "two"), "1 two"),
    (robogene.Bottle.from_text("[ok] 3.5"), "[ok] 3.5"),
])
def test_handler_results(network, answer, text):
    with robogene.RpcServer("/py/r", lambda request, info: answer, network=network):
        with robogene.RpcClient(server="/py/r", network=network) as c:
            assert c.call([1]).to_text() == text


def test_a_raising_handler_replies_fail_and_reports(network, monkeypatch):
    reported = []
    monkeypatch.setattr(sys, "unraisablehook", lambda u: reported.append(u))

    def handler(request, info):
        if request[0].as_int() < 0:
            raise ValueError("negative")
        if request[0].as_int() == 0:
            return {"not": "a bottle"}
        return [request[0].as_int()]
    with robogene.RpcServer("/py/strict", handler, network=network):
        with robogene.RpcClient(server="/py/strict", network=network) as c:
            assert c.call([-1]).to_text() == '[fail] "ValueError: negative"'
            assert c.call([0]).to_text().startswith('[fail] "TypeError: an RpcServer handler\'s reply must be')
            assert c.call([7]).to_text() == "7", "the connection survives"
    assert [type(u.exc_value) for u in reported] == [ValueError, TypeError]


def test_read_and_reply(network):
    with robogene.RpcServer("/py/manual", network=network) as server:
        def serve_two():
            for _ in range(2):
                request, info = server.read_with_info(timeout=10)
                server.reply([request.to_text(), info.reply_expected])
        t = threading.Thread(target=serve_two)
        t.start()
        with robogene.RpcClient(server="/py/manual", network=network) as c:
            assert c.call([1, 2]).to_text() == '"1 2" true'
            assert c.call(["x"]).to_text() == 'x true'
        t.join(10)
        assert server.read(timeout=0.1) is None


def test_serve_none_goes_back_to_read(network):
    with robogene.RpcServer("/py/toggle", lambda r, i: ["handler"], network=network) as server:
        with robogene.RpcClient(server="/py/toggle", network=network) as c:
            assert c.call([1]).to_text() == "handler"
            server.serve(None)
            t = threading.Thread(target=lambda: (server.read(timeout=10), server.reply(["manual"])))
            t.start()
            assert c.call([1]).to_text() == "manual"
            t.join(10)


def test_client_errors(network):
    with pytest.raises(robogene.NetworkError, match="not connected"):
        robogene.RpcClient().call([1])
    with pytest.raises(robogene.Error, match="/py/nobody"):
        robogene.RpcClient(server="/py/nobody", network=network)
    server = robogene.RpcServer("/py/gone", lambda r, i: r, network=network)
    c = robogene.RpcClient(server="/py/gone", network=network)
    assert c.call([1]).to_text() == "1"
    server.close()
    with pytest.raises(robogene.NetworkError, match="/py/gone"):
        c.call([1])
    c.close()


def test_network_rpc_one_shot(network):
    with robogene.RpcServer("/py/once", lambda r, i: [i.sender], network=network):
        assert network.rpc("/py/once", robogene.Bottle([1])).to_text() == "anon_rpc"
        assert network.rpc("/py/once", [1]).to_text() == "anon_rpc"
        with pytest.raises(TypeError, match="Network.rpc's request must be a Bottle, list or tuple, not int"):
            network.rpc("/py/once", 1)
    with pytest.raises(robogene.NetworkError, match="no port /py/once is registered"):
        network.rpc("/py/once", robogene.Bottle([1]))
