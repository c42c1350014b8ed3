# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""`robogene server` + `robogene name ...` end to end: outputs as `yarp name` prints them
(yarp-captures/yarp_name_cmds.txt), persistence across restarts, stale entries, errors."""
from __future__ import annotations

import os
import signal
import socket
import time

import pytest

pytestmark = pytest.mark.timeout(60)


def ok(result):
    assert result.returncode == 0, f"exit {result.returncode}\nstdout: {result.stdout}\nstderr: {result.stderr}"
    return result.stdout


def test_register_query_unregister_print_like_yarp_name(name_server, cli):
    first = name_server.port + 2
    assert ok(cli("name", "register", "/foo")) == f"registration name /foo ip 127.0.0.1 port {first} type tcp\n\n"
    assert ok(cli("name", "register", "/bar", "tcp", "127.0.0.1", "12345")) == \
        "registration name /bar ip 127.0.0.1 port 12345 type tcp\n\n"
    assert ok(cli("name", "query", "/bar")) == "registration name /bar ip 127.0.0.1 port 12345 type tcp\n\n"
    assert ok(cli("name", "unregister", "/foo")) == "Unregistered name.\n"
    assert ok(cli("name", "unregister", "/bar")) == "Unregistered name.\n"
    gone = cli("name", "query", "/bar")
    assert gone.returncode == 1
    assert "/bar is not registered" in gone.stderr


def test_list_with_prefix_set_get_check(name_server, cli):
    for name, port in (("/motors/rpc:i", 10004), ("/motors/command:i", 10005), ("/motorsX", 10009)):
        ok(cli("name", "register", name, "tcp", "127.0.0.1", str(port)))
    assert ok(cli("name", "list", "/motors")) == (
        "registration name /motors/command:i ip 127.0.0.1 port 10005 type tcp\n"
        "registration name /motors/rpc:i ip 127.0.0.1 port 10004 type tcp\n"
        "*** end of message\n")
    assert ok(cli("name", "set", "/motors/rpc:i", "offers", "tcp", "text", "fast_tcp")) == \
        "port /motors/rpc:i property offers = fast_tcp tcp text\n*** end of message\n"
    assert ok(cli("name", "check", "/motors/rpc:i", "offers", "tcp")) == \
        "port /motors/rpc:i property offers value tcp present true\n*** end of message\n"
    assert ok(cli("name", "set", "/motors/rpc:i", "process", "8398"))
    assert ok(cli("name", "get", "/motors/rpc:i", "process")) == \
        "port /motors/rpc:i property process = 8398\n*** end of message\n"
    everything = ok(cli("name", "list"))
    assert f"registration name /root ip 127.0.0.1 port {name_server.port} type tcp\n" in everything


def test_restart_keeps_registrations(start_name_server, cli, fake_port):
    alive = fake_port()
    server = start_name_server()
    ok(cli("name", "register", "/kept", "tcp", "127.0.0.1", str(alive.port)))
    ok(cli("name", "set", "/kept", "process", "4242"))
    assert server.proc.stop() == 0, server.proc.describe()
    again = start_name_server(port=server.port, db=server.db)
    assert ok(cli("name", "query", "/kept")) == f"registration name /kept ip 127.0.0.1 port {alive.port} type tcp\n\n"
    assert "process = 4242" in ok(cli("name", "get", "/kept", "process"))
    assert again.port == server.port


def test_registrations_survive_a_killed_server(start_name_server, cli, fake_port):
    alive = fake_port()
    server = start_name_server()
    ok(cli("name", "register", "/crash-proof", "tcp", "127.0.0.1", str(alive.port)))
    server.proc.signal(signal.SIGKILL)
    server.proc.wait_exit()
    start_name_server(port=server.port, db=server.db)
    assert "/crash-proof" in ok(cli("name", "query", "/crash-proof"))


def test_stale_entries_are_dropped(start_name_server, cli, fake_port):
    start_name_server("--stale-grace", "0", "--recheck", "0")
    port = fake_port()
    ok(cli("name", "register", "/mortal", "tcp", "127.0.0.1", str(port.port)))
    assert "/mortal" in ok(cli("name", "query", "/mortal"))
    assert port.connections >= 1, "the server did not probe the registered port"
    port.close()
    dropped = cli("name", "query", "/mortal")
    assert dropped.returncode == 1, dropped.stdout
    assert "/mortal" not in ok(cli("name", "list"))


def test_something_that_is_not_a_port_is_stale(start_name_server, cli):
    start_name_server("--stale-grace", "0")
    impostor = socket.socket()
    impostor.bind(("127.0.0.1", 0))
    impostor.listen(4)  # accepts connections but never answers the handshake
    try:
        ok(cli("name", "register", "/impostor", "tcp", "127.0.0.1", str(impostor.getsockname()[1])))
        assert cli("name", "query", "/impostor").returncode == 1
    finally:
        impostor.close()


def test_young_registrations_are_spared_during_the_grace_period(start_name_server, cli):
    start_name_server("--stale-grace", "30")
    ok(cli("name", "register", "/opening", "tcp", "127.0.0.1", "1"))  # nothing listens at port 1
    assert "/opening" in ok(cli("name", "query", "/opening"))


def test_periodic_sweep_drops_dead_entries_without_a_query(start_name_server, cli):
    server = start_name_server("--stale-grace", "0", "--sweep", "0.2")
    ok(cli("name", "register", "/ghost", "tcp", "127.0.0.1", "1"))
    server.proc.wait_for_line(r"dropped stale registration /ghost", stream="err")


def test_server_down_is_a_clear_error(cli, yarp_env):
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        free = s.getsockname()[1]
    r = cli("name", "query", "/x", "--server", f"127.0.0.1:{free}")
    assert r.returncode == 1
    assert f"name server at 127.0.0.1:{free} unreachable" in r.stderr
    assert "refused" in r.stderr


@pytest.mark.parametrize("bad", ["nohostport", "127.0.0.1:", ":10000", "127.0.0.1:99999", "127.0.0.1:abc"])
def test_bad_server_option_is_a_usage_error(cli, bad):
    r = cli("name", "list", "--server", bad)
    assert r.returncode == 2
    assert "--server" in r.stderr and "HOST:PORT" in r.stderr or "must be a whole number" in r.stderr


def test_bad_yarp_conf_names_file_and_line(cli, yarp_env):
    conf = os.path.join(yarp_env["YARP_CONFIG_HOME"], "yarp.conf")
    with open(conf, "w") as f:
        f.write("127.0.0.1 notaport yarp\n")
    r = cli("name", "list")
    assert r.returncode == 1
    assert f"{conf}:1" in r.stderr


def test_errors_from_the_server_reach_the_user(name_server, cli):
    r = cli("name", "set", "/nobody", "process", "1")
    assert r.returncode == 1
    assert "port /nobody is not registered" in r.stderr
    r = cli("name", "register", "/x", "tcp", "127.0.0.1", "banana")
    assert r.returncode == 1 and "port number or '...'" in r.stderr
    r = cli("name", "frobnicate")
    assert r.returncode == 2 and "unknown name sub-command" in r.stderr


def test_server_refuses_a_database_that_is_not_one(start_name_server, procs, yarp_env, robogene_bin, tmp_path):
    bogus = tmp_path / "bogus.db"
    bogus.write_text("definitely not sqlite, but long enough to look like a header of some kind\n" * 4)
    proc = procs.start("server", [robogene_bin, "server", "--socket", "0", "--db", str(bogus)], yarp_env)
    assert proc.wait_exit() == 1
    proc.wait_for_line(str(bogus), stream="err")


def test_server_reports_a_port_in_use(name_server, procs, yarp_env, robogene_bin, tmp_path):
    proc = procs.start("second server", [robogene_bin, "server", "--socket", str(name_server.port),
                                          "--db", str(tmp_path / "other.db")], yarp_env)
    assert proc.wait_exit() == 1
    proc.wait_for_line(str(name_server.port), stream="err")


def test_server_stops_cleanly_on_sigint(name_server):
    name_server.proc.signal(signal.SIGINT)
    assert name_server.proc.wait_exit() == 0
    name_server.proc.wait_for_line("Name server stopped")


def test_version_and_help(cli):
    assert ok(cli("version")).startswith("robogene ")
    text = ok(cli("help"))
    for command in ("server", "name"):
        assert f"  {command} " in text
    assert "usage: robogene server" in ok(cli("help", "server"))
    assert cli("help", "nonsense").returncode == 2
    assert cli("nonsense").returncode == 2


def test_server_stops_cleanly_with_clients_connected(start_name_server, tmp_path):
    # Regression: a session finishing during shutdown left a dangling pointer that stop() used.
    for attempt in range(5):
        server = start_name_server(db=str(tmp_path / f"names{attempt}.db"))
        clients = []
        for i in range(8):
            c = socket.create_connection((server.host, server.port), timeout=5)
            c.sendall(b"CONNECT idle\r\n" if i % 2 else b"NAME_SERVER query /root\n")
            clients.append(c)
        time.sleep(0.05)
        server.proc.signal(signal.SIGTERM)
        assert server.proc.wait_exit() == 0, server.proc.describe()
        for c in clients:
            c.close()


def free_udp_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_detect_finds_the_server_over_multicast_without_yarp_conf(start_name_server, cli, yarp_env):
    # A group port of this test's own ($YARP_PORT_RANGE, as YARP reads it), so that no other
    # name server on this machine answers.
    yarp_env["YARP_PORT_RANGE"] = str(free_udp_port())
    server = start_name_server()
    listing = ok(cli("name", "list"))
    assert f"registration name fallback ip 224.2.1.1 port {yarp_env['YARP_PORT_RANGE']} type mcast" in listing
    conf = os.path.join(yarp_env["YARP_CONFIG_HOME"], "yarp.conf")
    os.remove(conf)
    found = ok(cli("detect", "--ip", "127.0.0.1"))
    assert found == f"/root is available at ip 127.0.0.1 port {server.port}\n"
    assert not os.path.exists(conf)
    ok(cli("detect", "--write", "--ip", "127.0.0.1"))
    with open(conf) as f:
        assert f.read().split() == ["127.0.0.1", str(server.port), "yarp"]


def test_detect_without_a_fallback_fails_clearly(start_name_server, cli, yarp_env):
    yarp_env["YARP_PORT_RANGE"] = str(free_udp_port())
    start_name_server("--no-fallback")
    assert "fallback" not in ok(cli("name", "list"))
    r = cli("detect", "--ip", "127.0.0.1", "--timeout", "0.6")
    assert r.returncode == 1
    assert "no name server answered for /root on the multicast group 224.2.1.1:" in r.stderr
