# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The name server seen through raw sockets, as telnet and YARP 3 clients see it: the paper's
walkthrough (section 4.4), the name_ser bytes of yarp-captures/yarp_write_to_sniff.flows.txt,
text_ack, binary tcp, and robustness against garbage, vanishing and concurrent clients."""
from __future__ import annotations

import socket
import struct
import threading
import time

import pytest

import robogene

pytestmark = pytest.mark.timeout(60)


def connect(server) -> socket.socket:
    s = socket.create_connection((server.host, server.port), timeout=5)
    return s


def read_until(s: socket.socket, marker: bytes, limit: int = 1 << 20) -> bytes:
    data = b""
    while marker not in data:
        chunk = s.recv(65536)
        if not chunk:
            raise AssertionError(f"connection closed before {marker!r}; got {data!r}")
        data += chunk
        assert len(data) < limit
    return data


def read_all(s: socket.socket) -> bytes:
    data = b""
    while True:
        chunk = s.recv(65536)
        if not chunk:
            return data
        data += chunk


def name_ser(server, line: bytes) -> bytes:
    """One request the way YARP's NameClient sends it: a fresh connection, one line."""
    with connect(server) as s:
        s.sendall(line)
        s.shutdown(socket.SHUT_WR)
        return read_all(s)


def test_paper_walkthrough_verbatim(name_server, cli):
    cli("name", "register", "/motors", "tcp", "127.0.0.1", "10022")
    with connect(name_server) as s:
        s.sendall(b"CONNECT foo\r\n")
        assert read_until(s, b"\r\n") == b"Welcome foo\r\n"
        s.sendall(b"d\r\nhelp\r\n")
        help_text = read_until(s, b"*** end of message\r\n")
        for command in (b"query", b"register", b"list", b"unregister"):
            assert command in help_text
        s.sendall(b"d\r\nquery /motors\r\n")
        assert read_until(s, b"*** end of message\r\n") == (
            b"registration name /motors ip 127.0.0.1 port 10022 type tcp\r\n*** end of message\r\n")
        s.sendall(b"*\r\n")
        described = read_until(s, b"*** end of message\r\n")
        assert described.startswith(f"This is /root at tcp://127.0.0.1:{name_server.port}/\r\n".encode())
        assert b"input connection from foo to /root using text" in described
        s.sendall(b"?\r\n")
        assert b"d       the next line is a request" in read_until(s, b"*** end of message\r\n")
        s.sendall(b"q\r\n")
        assert read_all(s) == b""


def test_telnet_line_endings_and_unknown_lines(name_server):
    with connect(name_server) as s:
        s.sendall(b"CONNECT telnet-user\n")  # a bare \n is a line end too
        assert read_until(s, b"\r\n") == b"Welcome telnet-user\r\n"
        s.sendall(b"\r\nlist\r\n")  # ("query" would start with q, which closes, as in YARP)
        assert b"type d, then the request on the next line" in read_until(s, b"\r\n")
        s.sendall(b"d\r\n(query\r\n/root)\r\n")  # an open bracket pulls in the next line
        assert b"*** error" in read_until(s, b"*** end of message\r\n")


def test_captured_registration_sequence_byte_for_byte(name_server):
    p = name_server.port + 2
    offers = b"http name_ser local tcp fast_tcp mcast udp text text_ack human shmem unix_stream"
    sorted_offers = b"fast_tcp http human local mcast name_ser shmem tcp text text_ack udp unix_stream"
    exchange = [
        (b"NAME_SERVER query /w\n", b"*** end of message\r\n"),
        (b"NAME_SERVER register /w\r\n",
         b"registration name /w ip 127.0.0.1 port %d type tcp\r\n*** end of message\r\n" % p),
        (b"NAME_SERVER set /w offers " + offers + b"\r\n",
         b"port /w property offers = " + sorted_offers + b"\r\n*** end of message\r\n"),
        (b"NAME_SERVER set /w accepts " + offers + b"\r\n",
         b"port /w property accepts = " + sorted_offers + b"\r\n*** end of message\r\n"),
        (b"NAME_SERVER set /w ips 127.0.0.1 192.0.2.2 ::1 fd00::2 fe80::fc:ff:fe00:1%4\r\n",
         b"port /w property ips = 127.0.0.1 192.0.2.2 ::1 fd00::2 fe80::fc:ff:fe00:1%4\r\n*** end of message\r\n"),
        (b"NAME_SERVER set /w process 7332\r\n", b"port /w property process = 7332\r\n*** end of message\r\n"),
        (b"NAME_SERVER announce /w\n", b"[ok]\r\n"),
        (b"NAME_SERVER query /w\n",
         b"registration name /w ip 127.0.0.1 port %d type tcp\r\n*** end of message\r\n" % p),
        (b"NAME_SERVER unregister /w\n", b"*** end of message\r\n"),
    ]
    for request, expected in exchange:
        assert name_ser(name_server, request) == expected, request


def test_text_ack_carrier_acks_every_message(name_server):
    with connect(name_server) as s:
        s.sendall(b"CONNACK admin\r\n")
        assert read_until(s, b"\r\n") == b"Welcome admin\r\n"
        s.sendall(b"a\r\n[list] [out] \"/r\"\r\n")
        assert read_until(s, b"<ACK>\r\n") == b"\r\n<ACK>\r\n"  # as a port with no such output answers
        s.sendall(b"a\r\n[ver]\r\n")
        assert read_until(s, b"<ACK>\r\n") == b"[ver] 1 2 3\r\n<ACK>\r\n"
        s.sendall(b"d\r\nquery /root\r\n")
        assert read_until(s, b"<ACK>\r\n").endswith(b"*** end of message\r\n<ACK>\r\n")


def tcp_handshake(server, specifier: int = 7777 + 3 + 128) -> socket.socket:
    s = connect(server)
    s.sendall(b"YA" + struct.pack("<i", specifier) + b"RP" + struct.pack("<i", 6) + b"/test\0")
    reply = read_exactly(s, 8)
    assert reply == b"YA" + struct.pack("<i", server.port) + b"RP"
    return s


def read_exactly(s: socket.socket, n: int) -> bytes:
    data = b""
    while len(data) < n:
        chunk = s.recv(n - len(data))
        assert chunk, f"closed after {data!r}"
        data += chunk
    return data


def message(command: bytes, payload: bytes) -> bytes:
    """One indexed message: PortCommand block + payload block (reference 3.3)."""
    return (b"YA\x0a\0\0\0RP" + bytes([2, 1]) + b"\xff" * 8 + struct.pack("<iii", len(command), len(payload), 0)
            + command + payload)


D = b"\0\0\0\0~d\0\1"
ACK = b"YA\0\0\0\0RP"


def test_binary_tcp_bot_query_replies_a_bottle(name_server):
    with tcp_handshake(name_server) as s:
        s.sendall(message(D, robogene.Bottle.from_text("bot query /root").to_bytes()))
        expected = robogene.Bottle.from_text(
            f'port (name "/root") (ip "127.0.0.1") (port_number {name_server.port}) (carrier tcp)').to_bytes()
        assert read_exactly(s, len(expected)) == expected
        assert read_exactly(s, 8) == ACK
        # A plain command over binary tcp gets yarpserver's raw text lines back.
        s.sendall(message(D, robogene.Bottle.from_text("query /root").to_bytes()))
        text = f"registration name /root ip 127.0.0.1 port {name_server.port} type tcp\r\n*** end of message\r\n"
        assert read_exactly(s, len(text)) == text.encode()
        assert read_exactly(s, 8) == ACK
        # 'D' = no reply wanted: only the ack comes back, but the request is carried out.
        s.sendall(message(b"\0\0\0\0~D\0\1", robogene.Bottle.from_text("register /silent tcp 127.0.0.1 4000").to_bytes()))
        assert read_exactly(s, 8) == ACK
        s.sendall(b"YA\x0a\0\0\0RP\x01\x01" + b"\xff" * 8 + struct.pack("<ii", 10, 0) + b"\x02\0\0\0~\0\0\1q\0")
        assert read_exactly(s, 8) == ACK
        assert read_all(s) == b""
    assert b"port 4000" in name_ser(name_server, b"NAME_SERVER query /silent\n")


def test_fast_tcp_has_no_acks(name_server):
    with tcp_handshake(name_server, 7777 + 3) as s:
        s.sendall(message(D, robogene.Bottle.from_text("bot query /nobody").to_bytes()))
        expected = robogene.Bottle.from_text('port (error -2 "port not known")').to_bytes()
        assert read_exactly(s, len(expected)) == expected
        s.settimeout(0.3)
        with pytest.raises(socket.timeout):
            s.recv(1)


def still_serving(server) -> None:
    assert name_ser(server, b"NAME_SERVER query /root\n").startswith(b"registration name /root")


GARBAGE = [
    b"",                                            # connect and leave
    b"\x00\x01\x02",                                # fewer than 8 header bytes
    b"\xde\xad\xbe\xef" * 8,                        # unknown carrier
    b"NAME_SERXYZ nonsense\n",                      # name_ser without NAME_SERVER
    b"NAME_SERVER " + b"x" * 200000,                # an endless line
    b"NAME_SERVER register /x tcp 127.0.0.1 \"unterminated\n",
    b"CONNECT ",                                    # no name, then gone
    b"CONNECT x\r\nd\r\n(((((((((\r\n",             # unbalanced request, then gone
    b"YA\xe4\x1e\0\0RP" + struct.pack("<i", -5),     # negative name length
    b"YA\xe4\x1e\0\0RP" + struct.pack("<i", 10**6),  # huge name length
    b"YA\xe4\x1e\0\0RP\x03\0\0\0/w\0" + b"YA\x0b\0\0\0RP",  # bad index length
    b"YA\xe4\x1e\0\0RP\x03\0\0\0/w\0" + b"YA\x0a\0\0\0RP\x01\x01" + b"\xff" * 8 + struct.pack("<ii", 2**30, 0),
    b"YA\xe4\x1e\0\0RP\x03\0\0\0/w\0" + message(D, b"\x00\x01\x00\x00\x05\x00\x00\x00"),  # truncated bottle
    b"YA\xe4\x1e\0\0RP\x03\0\0\0/w\0" + message(b"\0\0\0\0~Z\0\1", b""),  # unknown PortCommand
]


@pytest.mark.parametrize("garbage", GARBAGE, ids=range(len(GARBAGE)))
def test_malformed_input_never_kills_the_server(name_server, garbage):
    with connect(name_server) as s:
        try:
            s.sendall(garbage)
            s.settimeout(2)
            s.recv(65536)
        except (socket.timeout, ConnectionResetError, BrokenPipeError):
            pass
    still_serving(name_server)
    assert name_server.proc.popen.poll() is None


def test_binary_garbage_bottle_gets_an_error_reply(name_server):
    with tcp_handshake(name_server) as s:
        s.sendall(message(D, b"\x00\x01\x00\x00\x05\x00\x00\x00"))
        reply = s.recv(65536)
        assert b"bad bottle" in reply
    still_serving(name_server)


def test_many_concurrent_clients(name_server):
    errors: list[str] = []

    def client(i: int) -> None:
        try:
            for j in range(5):
                name = f"/c{i}/{j}"
                reg = name_ser(name_server, f"NAME_SERVER register {name} tcp 127.0.0.1 {20000 + i * 10 + j}\r\n".encode())
                assert f"registration name {name} ".encode() in reg, reg
                q = name_ser(name_server, f"NAME_SERVER query {name}\n".encode())
                assert f"port {20000 + i * 10 + j} ".encode() in q, q
        except Exception as e:  # collected and reported below
            errors.append(f"client {i}: {e!r}")

    threads = [threading.Thread(target=client, args=(i,)) for i in range(40)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(30)
    assert not errors, errors[:5]
    listing = name_ser(name_server, b"NAME_SERVER list\n")
    assert listing.count(b"registration name /c") == 200


def test_client_that_vanishes_mid_request(name_server):
    for _ in range(20):
        s = connect(name_server)
        s.sendall(b"NAME_SERVER list")  # no newline, then gone
        s.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
        s.close()  # RST
    time.sleep(0.2)
    still_serving(name_server)
