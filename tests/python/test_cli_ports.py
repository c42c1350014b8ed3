# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""`robogene read / write / rpc / connect / disconnect / ping / ls` end to end, through a real
`robogene server`: bottles in text form as `yarp read` prints them (yarp-captures/yarp_read_out.txt),
`Response: ...` as `yarp rpc` prints (yarp_rpc_motors.txt), connections changed at run time."""
from __future__ import annotations

import signal
import socket
import struct
import threading
import time

import pytest

import robogene

pytestmark = pytest.mark.timeout(60)

CAPTURED_LINES = [
    '1 2.5 hi [set]',
    '(nested (list 1 2) "with space") {1 2 255} 0.100000000000000005551 -3 100000 '
    '1.0000000000000000525e+300 inf -inf nan 12345678901 true false 16',
]


def ok(result):
    assert result.returncode == 0, f"exit {result.returncode}\nstdout: {result.stdout}\nstderr: {result.stderr}"
    return result.stdout


def start_read(procs, robogene_bin, yarp_env, name, *extra):
    proc = procs.start(f"read {name}", [robogene_bin, "read", name, *extra], yarp_env)
    proc.wait_for_line(rf"Port {name} active at tcp://", stream="err")
    return proc


def test_write_to_read_prints_bottles_as_yarp_read(name_server, procs, robogene_bin, yarp_env, cli):
    reader = start_read(procs, robogene_bin, yarp_env, "/r")
    typed = ('1 2.5 "hi" [set]\n'
             '(nested (list 1 2) "with space") {1 2 255} 0.1 -3 100000 1e300 inf -inf nan 12345678901 true false 0x10\n')
    ok(cli("write", "/w", "/r", input=typed))
    for line in CAPTURED_LINES:
        reader.wait_for_line("^" + __import__("re").escape(line) + "$")
    assert reader.out == CAPTURED_LINES
    # write unregistered its port when stdin ended
    assert cli("name", "query", "/w").returncode == 1


def test_multiline_bottles_and_bad_lines(name_server, procs, robogene_bin, yarp_env, cli):
    reader = start_read(procs, robogene_bin, yarp_env, "/r")
    r = cli("write", "/w", "/r", input='(a\nb) "two\nlines"\n1 2 \\\n3\n"never closed\n')
    assert r.returncode == 1, "an unsendable line must make the exit status non-zero"
    assert "stdin line 6" in r.stderr and "unfinished bottle" in r.stderr
    reader.wait_for_line(r"^1 2 3$")
    assert reader.out == ['(a b) "two\\nlines"', "1 2 3"]


def test_read_refuses_messages_over_its_size_limit(name_server, procs, robogene_bin, yarp_env, cli):
    reader = start_read(procs, robogene_bin, yarp_env, "/r", "--max-message", "1k")
    cli("write", "/big", "/r", input='"' + "x" * 2000 + '"\n')  # its connection is closed under it
    reader.wait_for_line(r"more than the maximum message size of 1024", stream="err")
    ok(cli("write", "/small", "/r", input="still here\n"))
    reader.wait_for_line("^still here$")
    assert reader.out == ["still here"]
    bad = cli("read", "/r2", "--max-message", "lots")
    assert bad.returncode == 2 and "--max-message must be a size in bytes" in bad.stderr


def test_read_stops_cleanly_and_unregisters(name_server, procs, robogene_bin, yarp_env, cli):
    reader = start_read(procs, robogene_bin, yarp_env, "/quiet")
    assert "/quiet" in ok(cli("name", "query", "/quiet"))
    reader.signal(signal.SIGTERM)
    assert reader.wait_exit() == 0
    assert cli("name", "query", "/quiet").returncode == 1


def test_connect_and_disconnect_at_run_time(name_server, procs, robogene_bin, yarp_env, cli):
    reader = start_read(procs, robogene_bin, yarp_env, "/r")
    writer = procs.start("write /w", [robogene_bin, "write", "/w"], yarp_env)
    writer.wait_for_line(r"Port /w active", stream="err")
    assert ok(cli("connect", "/w", "/r")) == "Success: Added connection from /w to tcp://r\n"
    writer.send("first\n")
    reader.wait_for_line("^first$")
    ls = ok(cli("ls"))
    assert "/w  tcp://127.0.0.1:" in ls and "  -> /r (tcp)" in ls and "  <- /w (tcp)" in ls
    assert ok(cli("disconnect", "/w", "/r")) == "Success: Removed connection from /w to /r\n"
    writer.send("lost\n")
    assert ok(cli("connect", "/w", "/r", "text")) == "Success: Added connection from /w to text://r\n"
    writer.send("second\n")
    reader.wait_for_line("^second$")
    assert "lost" not in reader.out
    assert "  -> /r (text)" in ok(cli("ls", "/w"))
    writer.close_stdin()
    assert writer.wait_exit() == 0


def test_read_with_a_source_connects_it(name_server, procs, robogene_bin, yarp_env, cli):
    writer = procs.start("write /src", [robogene_bin, "write", "/src"], yarp_env)
    writer.wait_for_line(r"Port /src active", stream="err")
    reader = start_read(procs, robogene_bin, yarp_env, "/sink", "/src")
    reader.wait_for_line(r"Success: Added connection from /src to tcp://sink", stream="err")
    writer.send("hello from src\n")
    reader.wait_for_line("^hello from src$")


class EchoRpcPort:
    """A port written with raw sockets: registers itself, answers each 'd' request with
    [is] <request...> [ok], and acks (a stand-in for a device's rpc:i port)."""

    def __init__(self, server, name: str):
        self.sock = socket.socket()
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(4)
        self.port = self.sock.getsockname()[1]
        self.senders: list[str] = []
        with socket.create_connection((server.host, server.port), timeout=5) as s:
            s.sendall(f"NAME_SERVER register {name} tcp 127.0.0.1 {self.port}\n".encode())
            s.shutdown(socket.SHUT_WR)
            while s.recv(4096):
                pass
        threading.Thread(target=self._serve, daemon=True).start()

    @staticmethod
    def _read(c, n):
        data = b""
        while len(data) < n:
            chunk = c.recv(n - len(data))
            if not chunk:
                raise EOFError
            data += chunk
        return data

    def _serve(self):
        while True:
            try:
                c, _ = self.sock.accept()
            except OSError:
                return
            threading.Thread(target=self._talk, args=(c,), daemon=True).start()

    def _talk(self, c):
        try:
            self._read(c, 8)
            (n,) = struct.unpack("<i", self._read(c, 4))
            self.senders.append(self._read(c, n).rstrip(b"\0").decode())
            c.sendall(b"YA" + struct.pack("<i", self.port) + b"RP")
            while True:
                self._read(c, 8)
                counts = self._read(c, 10)
                k = counts[0] + counts[1]
                body = self._read(c, sum(struct.unpack(f"<{k}i", self._read(c, 4 * k))))
                if body[5:6] == b"d":
                    request = robogene.Bottle.from_bytes(body[8:])
                    c.sendall(robogene.Bottle.from_text("[is] " + request.to_text() + " [ok]").to_bytes())
                c.sendall(b"YA\0\0\0\0RP")
                if body[5:6] == b"\0" and body[8:9] == b"q":
                    return
        except (OSError, EOFError):
            pass
        finally:
            c.close()

    def close(self):
        try:
            self.sock.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass
        self.sock.close()


def test_rpc_prints_responses_like_yarp_rpc(name_server, cli):
    port = EchoRpcPort(name_server, "/motors/rpc:i")
    try:
        out = ok(cli("rpc", "/motors/rpc:i", input="get axes\n[get] [axes]\n\n[set] [pos] 1 25.0\n"))
        assert out == ("Response: [is] get axes [ok]\n"
                       "Response: [is] [get] [axes] [ok]\n"
                       "Response: [is] [set] [pos] 1 25.0 [ok]\n")
        assert port.senders == ["anon_rpc"], "yarp rpc connects anonymously"
    finally:
        port.close()


def test_rpc_to_the_name_server_itself(name_server, cli):
    out = ok(cli("rpc", "/root", input="bot query /root\n"))
    assert out == (f'Response: port (name "/root") (ip "127.0.0.1") (port_number {name_server.port}) '
                   "(carrier tcp)\n")


def test_ping(name_server, procs, robogene_bin, yarp_env, cli):
    start_read(procs, robogene_bin, yarp_env, "/r")
    out = ok(cli("ping", "/r"))
    assert out.startswith("Port /r is alive at tcp://127.0.0.1:") and "answered [ver] 1 2 3" in out
    gone = cli("ping", "/nobody")
    assert gone.returncode == 1 and "/nobody is not registered" in gone.stderr


@pytest.mark.parametrize("argv", [
    ["read", "/nobody-writes", "/missing-source"],
    ["write", "/w", "/missing"],
    ["rpc", "/missing"],
    ["connect", "/missing", "/also-missing"],
    ["disconnect", "/missing", "/r"],
])
def test_unknown_ports_are_clear_errors(name_server, cli, argv):
    r = cli(*argv)
    assert r.returncode == 1, r
    assert "/missing" in r.stderr and "registered" in r.stderr
    # nothing was left registered behind
    assert "/nobody-writes" not in ok(cli("name", "list")) and "registration name /w " not in ok(cli("name", "list"))


@pytest.mark.parametrize("argv", [["read", "r"], ["write"], ["rpc"], ["connect", "/a"], ["ping", "x"]])
def test_usage_errors(cli, argv, name_server):
    r = cli(*argv)
    assert r.returncode == 2
    assert "usage: robogene " + argv[0] in r.stderr


def test_disconnecting_what_is_not_connected_fails(name_server, procs, robogene_bin, yarp_env, cli):
    start_read(procs, robogene_bin, yarp_env, "/r")
    writer = procs.start("write /w", [robogene_bin, "write", "/w"], yarp_env)
    writer.wait_for_line(r"Port /w active", stream="err")
    r = cli("disconnect", "/w", "/r")
    assert r.returncode == 1 and "disconnecting /w from /r failed" in r.stderr


def test_commands_without_a_server(cli, yarp_env):
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        free = s.getsockname()[1]
    for argv in (["read", "/r"], ["write", "/w"], ["rpc", "/x"], ["connect", "/a", "/b"], ["ls"], ["ping", "/x"]):
        r = cli(*argv, "--server", f"127.0.0.1:{free}", input="")
        assert r.returncode == 1, (argv, r)
        assert f"127.0.0.1:{free}" in r.stderr, (argv, r.stderr)


def test_read_envelope_option_prints_the_stamp(name_server, procs, robogene_bin, yarp_env, cli):
    reader = start_read(procs, robogene_bin, yarp_env, "/r", "--envelope")
    port = int(ok(cli("name", "query", "/r")).split()[6])
    with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
        s.sendall(b"YA\xe4\x1e\0\0RP" + struct.pack("<i", 5) + b"/env\0")
        assert s.recv(8)[:2] == b"YA"
        command = b"D 1053 1795328338.10597\0"
        header = struct.pack("<i", len(command)) + b"~\0\0\1" + command  # state:o's envelope form
        payload = robogene.Bottle.from_text("1.0 2.0 3.0 4.0").to_bytes()
        s.sendall(b"YA\x0a\0\0\0RP\x02\x01" + b"\xff" * 8 + struct.pack("<iii", len(header), len(payload), 0)
                  + header + payload)
        assert s.recv(8) == b"YA\0\0\0\0RP"
    reader.wait_for_line(r"^1053 1795328338\.10597 \| 1\.0 2\.0 3\.0 4\.0$")


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_write_interrupted_unregisters(name_server, procs, robogene_bin, yarp_env, cli, sig):
    writer = procs.start("write /w", [robogene_bin, "write", "/w"], yarp_env)
    writer.wait_for_line(r"Port /w active", stream="err")
    assert "/w" in ok(cli("name", "query", "/w"))
    writer.signal(sig)
    assert writer.wait_exit() == 0
    assert cli("name", "query", "/w").returncode == 1
