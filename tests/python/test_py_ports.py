# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""robogene.Port, Network and the value types from Python, through a real `robogene server`:
registering and unregistering, yarp.conf or an explicit server, reading with timeouts, replies,
envelopes, connections, and the errors for bad names and missing servers."""
from __future__ import annotations

import socket
import threading
import time

import pytest

import robogene

pytestmark = pytest.mark.timeout(60)


def unused_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_port_registers_and_the_context_manager_unregisters(network):
    with robogene.Port("/py/a", network=network) as p:
        assert p.is_open and p.name == "/py/a"
        where = network.query("/py/a")
        assert where == p.contact and where.host == "127.0.0.1" and where.port > 0
        assert where.uri == f"tcp://127.0.0.1:{where.port}/"
        assert "/py/a" in [c.name for c in network.list()]
        assert [c.name for c in network.list("/py/")] == ["/py/a"]
    assert not p.is_open
    assert network.query("/py/a") is None


def test_yarp_conf_is_honoured(name_server, python_yarp_env):
    conf = robogene.NameConfig.load()
    assert (conf.host, conf.port) == (name_server.host, name_server.port)
    assert conf.source.endswith("yarp.conf")
    with robogene.Port("/py/conf") as p:
        assert robogene.Network().query("/py/conf") == p.contact


def test_missing_yarp_conf_is_a_clear_error(python_yarp_env):
    with pytest.raises(robogene.Error, match="yarp.conf"):
        robogene.Port("/py/x")
    with pytest.raises(robogene.Error, match="yarp.conf"):
        robogene.Network()


def test_no_name_server_is_a_network_error():
    dead = robogene.Network(("127.0.0.1", unused_port()), timeout=2)
    with pytest.raises(robogene.NetworkError, match=r"name server at 127\.0\.0\.1:\d+ unreachable"):
        robogene.Port("/py/x", network=dead)
    with pytest.raises(robogene.NetworkError, match="unreachable"):
        dead.query("/py/x")


@pytest.mark.parametrize("bad", ["x", "", "no/slash"])
def test_bad_port_names_are_refused(network, bad):
    with pytest.raises(robogene.Error, match="must start with '/'"):
        robogene.Port(bad, network=network)
    assert network.query(bad) is None


def test_bad_arguments_are_refused(network):
    with pytest.raises(ValueError, match="server"):
        robogene.Network(("127.0.0.1", 0))
    with pytest.raises(robogene.Error, match="HOST:PORT|host:port|port"):
        robogene.Network("no-port-here")
    with pytest.raises(ValueError, match="timeout"):
        robogene.Port(timeout=-1)
    with pytest.raises(ValueError, match="either network= or at="):
        robogene.Port("/py/x", network=network, at=("127.0.0.1", 0))
    with pytest.raises(TypeError, match="use Bottle.from_text"):
        robogene.Port().write("1 2 3")
    with robogene.Port("/py/twice", network=network) as p:
        with pytest.raises(robogene.Error, match="already open"):
            p.open("/py/other", network=network)
        with pytest.raises(ValueError, match="timeout"):
            p.read(timeout=float("nan"))


def test_write_to_a_python_reader(network):
    with robogene.Port("/py/r", network=network) as reader, robogene.Port("/py/w", network=network) as writer:
        assert writer.write([1]) is False, "no output yet"
        writer.add_output("/py/r")
        assert writer.outputs == ["/py/r"]
        got = []
        t = threading.Thread(target=lambda: got.append(reader.read_with_info(timeout=10)))
        t.start()
        assert writer.write(robogene.Bottle.from_text('1 2.5 "hi" [set]'))
        t.join(10)
        bottle, info = got[0]
        assert bottle.to_text() == '1 2.5 hi [set]'
        assert (info.sender, info.carrier, info.envelope, info.reply_expected) == ("/py/w", "tcp", "", False)
        assert reader.inputs == ["/py/w"]
        assert writer.remove_output("/py/r") and writer.outputs == []


def test_read_times_out_and_zero_only_takes_what_waits(network):
    with robogene.Port("/py/quiet", network=network) as p:
        start = time.monotonic()
        assert p.read(timeout=0.3) is None
        assert 0.25 <= time.monotonic() - start < 3
        assert p.read(timeout=0) is None
    with pytest.raises(robogene.Error, match="not open"):
        robogene.Port().read(timeout=0)


def test_close_from_another_thread_ends_a_blocking_read(network):
    p = robogene.Port("/py/blocked", network=network)
    result = []
    t = threading.Thread(target=lambda: result.append(p.read()))
    t.start()
    time.sleep(0.3)
    start = time.monotonic()
    p.close()
    t.join(5)
    assert not t.is_alive() and result == [None]
    assert time.monotonic() - start < 3
    assert network.query("/py/blocked") is None


def test_read_and_reply_answers_write_with_reply(network):
    with robogene.Port("/py/srv", network=network) as srv, robogene.Port("/py/cli", network=network) as cli:
        cli.add_output("/py/srv")

        def answer():
            request = srv.read(timeout=10, will_reply=True)
            srv.reply([request[0].as_int() + 1, "done"])
        t = threading.Thread(target=answer)
        t.start()
        assert cli.write_with_reply([41]).to_text() == "42 done"
        t.join(5)
    assert robogene.Port().write_with_reply([1]) is None, "no output: None"


def test_envelopes_travel_with_the_message(network):
    with robogene.Port("/py/er", network=network) as r, robogene.Port("/py/ew", network=network) as w:
        w.add_output("/py/er")
        w.set_envelope(robogene.Stamp(7, 1795328338.10597))
        got = []
        t = threading.Thread(target=lambda: got.append(r.read_with_info(timeout=10)))
        t.start()
        w.write([1])
        t.join(10)
        _, info = got[0]
        assert info.envelope == "7 1795328338.10597"
        assert info.stamp == robogene.Stamp(7, 1795328338.10597)
        w.set_envelope(None)
        t = threading.Thread(target=lambda: got.append(r.read_with_info(timeout=10)))
        t.start()
        w.write([2])
        t.join(10)
        assert got[1][1].envelope == "" and got[1][1].stamp is None
    with pytest.raises(TypeError, match="Stamp, a str or None"):
        robogene.Port().set_envelope(3)


def test_network_connect_disconnect_between_python_ports(network):
    with robogene.Port("/py/cr", network=network), robogene.Port("/py/cw", network=network) as w:
        assert network.connect("/py/cw", "/py/cr") == "Added connection from /py/cw to tcp://py/cr"
        assert w.outputs == ["/py/cr"]
        reply = network.admin("/py/cw", robogene.Bottle.from_text("[list] [out]"))
        assert reply.to_python() == ["/py/cr"]
        assert network.disconnect("/py/cw", "/py/cr").startswith("Removed connection")
        with pytest.raises(robogene.NetworkError, match="Could not find an outgoing connection"):
            network.disconnect("/py/cw", "/py/cr")
        with pytest.raises(robogene.Error, match="/py/missing is not registered"):
            network.connect("/py/cw", "/py/missing")


def test_open_at_an_address_without_a_name_server():
    with robogene.Port("/py/direct", at=("127.0.0.1", 0)) as r, robogene.Port() as w:
        assert r.contact.port > 0 and r.contact.name == "/py/direct"
        w.add_output(r.contact)  # a Contact needs no name server
        assert w.outputs == ["/py/direct"]
        got = []
        t = threading.Thread(target=lambda: got.append(r.read_with_info(timeout=10)))
        t.start()
        assert w.write([1, 2])
        t.join(10)
        bottle, info = got[0]
        assert bottle.to_text() == "1 2" and info.sender == "anon_rpc", "an unopened port writes anonymously"


def test_value_types():
    c = robogene.Contact("/x", "udp", "10.0.0.1", 10002)
    assert c.uri == "udp://10.0.0.1:10002/" and repr(c).startswith("Contact(name='/x'")
    assert robogene.Stamp.parse("12 3.5") == robogene.Stamp(12, 3.5)
    assert robogene.Stamp.parse("not a stamp") is None
    assert robogene.Stamp(3, 0.25).to_text() == "3 0.25"
    assert robogene.BufferPolicy.STRICT != robogene.BufferPolicy.LATEST_ONLY


def test_network_register_query_unregister(network, name_server):
    assert (network.host, network.port, network.address) == (name_server.host, name_server.port, name_server.address)
    recorded = network.register("/py/by-hand", "tcp", "127.0.0.1", 15001)
    assert recorded == robogene.Contact("/py/by-hand", "tcp", "127.0.0.1", 15001)
    assert network.query("/py/by-hand") == recorded
    network.set_property("/py/by-hand", "offers", ["tcp", "text"])
    assert network.request("NAME_SERVER get /py/by-hand offers\n") == ["port /py/by-hand property offers = tcp text"]
    chosen = network.register("/py/chosen")
    assert chosen.port > 0 and chosen.host
    network.unregister("/py/by-hand")
    assert network.query("/py/by-hand") is None
    assert [c.name for c in network.list("/py/")] == ["/py/chosen"]
