# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The paper's section 4.4 against ordinary ports started by the CLI, with a raw socket as telnet
would be: CONNECT, help, *, d + a bottle, and r (reverse) to receive a port's output stream."""
from __future__ import annotations

import re
import socket

import pytest

pytestmark = pytest.mark.timeout(60)


def query(server, name: str) -> tuple[str, int]:
    with socket.create_connection((server.host, server.port), timeout=5) as s:
        s.sendall(f"NAME_SERVER query {name}\n".encode())
        s.shutdown(socket.SHUT_WR)
        reply = b""
        while chunk := s.recv(4096):
            reply += chunk
    m = re.match(rb"registration name \S+ ip (\S+) port (\d+) type", reply)
    assert m, reply
    return m.group(1).decode(), int(m.group(2))


def read_until(s: socket.socket, marker: bytes) -> bytes:
    data = b""
    while marker not in data:
        chunk = s.recv(65536)
        assert chunk, f"closed before {marker!r}; got {data!r}"
        data += chunk
    return data


def test_telnet_to_a_reader_port(name_server, procs, robogene_bin, yarp_env):
    reader = procs.start("read /demo", [robogene_bin, "read", "/demo"], yarp_env)
    reader.wait_for_line(r"Port /demo active", stream="err")
    host, port = query(name_server, "/demo")
    with socket.create_connection((host, port), timeout=5) as s:
        s.sendall(b"CONNECT foo\r\n")
        assert read_until(s, b"\r\n") == b"Welcome foo\r\n"
        s.sendall(b"*\r\n")
        described = read_until(s, b"\r\n")
        assert described.startswith(f"This is /demo at tcp://{host}:{port}/".encode()), described
        s.sendall(b"d\r\n[set] [pos] 0 100.0\r\n")
        reader.wait_for_line(r"^\[set\] \[pos\] 0 100\.0$")
        s.sendall(b"d\r\n(hello world) 42 3.5 \"a string\" [vocb]\r\n")
        reader.wait_for_line(r'^\(hello world\) 42 3\.5 "a string" \[vocb\]$')  # yarp_read_text_input.txt
        s.sendall(b"q\r\n")


def test_telnet_help_on_a_port(name_server, procs, robogene_bin, yarp_env):
    reader = procs.start("read /demo", [robogene_bin, "read", "/demo"], yarp_env)
    reader.wait_for_line(r"Port /demo active", stream="err")
    host, port = query(name_server, "/demo")
    with socket.create_connection((host, port), timeout=5) as s:
        s.sendall(b"CONNECT foo\r\nhelp\r\n")
        text = read_until(s, b"?       this help\r\n")
        assert text.startswith(b"Welcome foo\r\n")
        for command in (b"\r\nd ", b"\r\nq ", b"\r\nr ", b"\r\n*"):
            assert command in text, command


def test_reverse_streams_a_writers_output(name_server, procs, robogene_bin, yarp_env):
    writer = procs.start("write /motors", [robogene_bin, "write", "/motors"], yarp_env)
    writer.wait_for_line(r"Port /motors active", stream="err")
    host, port = query(name_server, "/motors")
    with socket.create_connection((host, port), timeout=5) as s:
        s.sendall(b"CONNECT foo\r\n")
        assert read_until(s, b"\r\n") == b"Welcome foo\r\n"
        s.sendall(b"r\r\n")
        # The writer only sends once it has the reversed output: retry the line until it arrives.
        received = b""
        s.settimeout(0.5)
        for _ in range(20):
            writer.send("100.0 0.0\n")
            try:
                received += s.recv(65536)
            except socket.timeout:
                continue
            if b"100.0 0.0\r\n" in received:
                break
        assert re.search(rb"do\r\n100\.0 0\.0\r\n", received), received
