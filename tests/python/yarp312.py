# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""YARP 3.12.3 without YARP: the fixtures captured from it (tests/vectors/yarp312/, README.md there)
and a server that answers as it answered.

* ``load(name)`` reads a fixture: its connections, each with the messages sent and the replies.
* ``ReplayServer`` is a tcp port in pure Python that answers every request with the reply YARP 3.12.3
  gave to the same bytes ([fail] to anything it was never asked, as YARP's control board answers an
  unknown request), answers admin messages over text_ack as YARP's ports do, and records every
  byte it receives, so that a test can say what our clients sent to a YARP 3.12.3 server. Asked
  to `[add]` an output, it connects to that port and streams the recorded messages of a stream
  (the control board's stateExt:o) with fresh envelopes."""
from __future__ import annotations

import socket
import struct
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Optional

FIXTURES = Path(__file__).resolve().parents[1] / "vectors" / "yarp312"
TCP = b"YA\xe4\x1e\x00\x00RP"
FAST_TCP = b"YA\x64\x1e\x00\x00RP"
UDP = b"YA\x61\x1e\x00\x00RP"
INDEX = b"YA\x0a\x00\x00\x00RP"
ACK = b"YA\x00\x00\x00\x00RP"


@dataclass
class Message:
    command: str                      # 'd' (a reply expected), 'D', 'q'
    payload: bytes
    envelope: str = ""
    reply: Optional[bytes] = None     # what YARP 3.12.3 answered ('d' only)


@dataclass
class Connection:
    carrier: str                      # tcp, fast_tcp, text_ack
    sender: str
    messages: list = field(default_factory=list)
    admin: list = field(default_factory=list)   # [(request text, [reply lines])] over text_ack


def load(name: str) -> list[Connection]:
    """The connections of fixture `name` (a file of tests/vectors/yarp312/)."""
    conns: list[Connection] = []
    path = FIXTURES / name
    for number, line in enumerate(path.read_text().splitlines(), 1):
        if not line or line.startswith("#"):
            continue
        word, _, rest = line.partition(" ")
        try:
            if word == "conn":
                carrier, _, sender = rest.partition(" ")
                conns.append(Connection(carrier, sender))
            elif word == ">":
                command, _, data = rest.partition(" ")
                payload, _, envelope = data.partition(" @ ")
                conns[-1].messages.append(Message(command, bytes.fromhex(payload), envelope))
            elif word == "<":
                conns[-1].messages[-1].reply = bytes.fromhex(rest)
            elif word == "a>":
                conns[-1].admin.append((rest, []))
            elif word == "a<":
                conns[-1].admin[-1][1].append(rest)
            else:
                raise ValueError(f"unknown line kind {word!r}")
        except (ValueError, IndexError) as e:
            raise ValueError(f"{path}:{number}: {e}") from None
    return conns


def exchanges(*names: str) -> dict[bytes, bytes]:
    """request payload -> YARP 3.12.3's reply, over the fixtures `names`."""
    out: dict[bytes, bytes] = {}
    for name in names:
        for conn in load(name):
            for m in conn.messages:
                if m.command == "d" and m.reply is not None:
                    out.setdefault(m.payload, m.reply)
    return out


def _read(sock: socket.socket, n: int) -> bytes:
    data = b""
    while len(data) < n:
        chunk = sock.recv(n - len(data))
        if not chunk:
            raise ConnectionError("closed")
        data += chunk
    return data


def _read_line(sock: socket.socket) -> str:
    data = b""
    while not data.endswith(b"\n"):
        data += _read(sock, 1)
    return data.decode(errors="replace").rstrip("\r\n")


def _message(command: bytes, payload: bytes) -> bytes:
    return INDEX + bytes([2, 1]) + b"\xff" * 8 + struct.pack("<iii", len(command), len(payload), 0) + command + payload


def _port_command(envelope: str) -> bytes:
    text = f"D {envelope}".encode() + b"\0"
    return struct.pack("<i", len(text)) + b"~\x00\x00\x01" + text


FAIL = bytes.fromhex("09010000010000006661696c")  # [fail]


class ReplayServer:
    def __init__(self, replies: dict[bytes, bytes], stream: Optional[list[bytes]] = None):
        self.replies = replies
        self.stream = stream or []
        self.received: list[tuple[str, str, bytes]] = []     # (sender, command, payload)
        self.admin: list[str] = []                            # admin requests, as text
        self.unknown: list[bytes] = []                        # requests YARP 3.12.3 was never asked
        self.resolve = None                                   # name -> (host, port), for [add]
        self.streamed = 0                                     # stream messages acked by the reader
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self._sock.bind(("127.0.0.1", 0))
        self._sock.listen(16)
        self.port = self._sock.getsockname()[1]
        threading.Thread(target=self._accept, daemon=True).start()

    def sent_bytes(self) -> bytes:
        """Everything received, payloads and admin text alike."""
        with self._lock:
            return b"".join(p for _, _, p in self.received) + "\n".join(self.admin).encode()

    def close(self) -> None:
        self._stop.set()
        self._sock.close()

    def _accept(self) -> None:
        while not self._stop.is_set():
            try:
                conn, _ = self._sock.accept()
            except OSError:
                return
            threading.Thread(target=self._serve, args=(conn,), daemon=True).start()

    def _serve(self, conn: socket.socket) -> None:
        try:
            with conn:
                head = _read(conn, 8)
                if head in (b"CONNACK ", b"CONNECT "):
                    self._text(conn, head == b"CONNACK ")
                elif head in (TCP, FAST_TCP):
                    self._binary(conn, head == TCP)
                elif head == UDP:
                    self._udp(conn)
        except (ConnectionError, OSError):
            pass

    def _sender(self, conn: socket.socket) -> str:
        (n,) = struct.unpack("<i", _read(conn, 4))
        return _read(conn, n).rstrip(b"\0").decode()

    def _binary(self, conn: socket.socket, acks: bool) -> None:
        sender = self._sender(conn)
        conn.sendall(b"YA" + struct.pack("<i", self.port) + b"RP")
        while True:
            if _read(conn, 8) != INDEX:
                return
            counts = _read(conn, 10)
            lengths = struct.unpack(f"<{counts[0] + counts[1]}i", _read(conn, 4 * (counts[0] + counts[1])))
            body = _read(conn, sum(lengths))
            command, payload = chr(body[5]), body[8:]
            if body[5] == 0:
                (n,) = struct.unpack("<i", body[:4])
                command, payload = payload[:n].decode(errors="replace")[0], payload[n:]
            with self._lock:
                self.received.append((sender, command, payload))
            if command == "q":
                if acks:
                    conn.sendall(ACK)
                return
            if command == "d":
                reply = self.replies.get(payload)
                if reply is None:
                    with self._lock:
                        self.unknown.append(payload)
                    reply = FAIL
                conn.sendall(reply)
            if acks:
                conn.sendall(ACK)

    def _udp(self, conn: socket.socket) -> None:
        sender = self._sender(conn)
        udp = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        udp.bind(("127.0.0.1", 0))
        conn.sendall(b"YA" + struct.pack("<i", udp.getsockname()[1]) + b"RP")
        udp.settimeout(0.2)

        def drain() -> None:
            with udp:
                while not self._stop.is_set():
                    try:
                        datagram = udp.recv(65536)
                    except socket.timeout:
                        continue
                    except OSError:
                        return
                    with self._lock:  # CRC and counter, then the message as on tcp
                        self.received.append((sender, "udp", datagram[8:]))
        threading.Thread(target=drain, daemon=True).start()

    def _text(self, conn: socket.socket, acks: bool) -> None:
        name = _read_line(conn)
        conn.sendall(f"Welcome {name}\r\n".encode())
        while True:
            key = _read_line(conn)
            if key == "q":
                return
            if key != "a":
                continue
            request = _read_line(conn)
            with self._lock:
                self.admin.append(request)
            reply = self._admin(request)
            conn.sendall(reply.encode() + b"\r\n" + (b"<ACK>\r\n" if acks else b""))

    def _admin(self, request: str) -> str:
        """YARP 3.12.3's answers (PortCore::adminBlock) for what clients ask here."""
        words = request.split()
        if words[:2] == ["[prop]", "[get]"]:
            return ""  # a property the port does not have: nothing
        if words[:1] == ["[list]"]:
            return ""
        if words[:1] == ["[add]"] and len(words) > 1:
            target = words[1].strip('"')
            carrier, _, name = target.rpartition(":/")  # "udp://c/stateExt:i" is /c/stateExt:i by udp
            threading.Thread(target=self._stream_to, args=(name if carrier else target,), daemon=True).start()
            return f'0 "Added connection to {target}\\r\\n"'
        if words[:1] == ["[del]"]:
            return '0 "Removed connection\\r\\n"'
        return '[fail] "send [help] for list of valid commands"'

    def _stream_to(self, name: str) -> None:
        """Sends the recorded stream messages to `name` over tcp, every 20 ms, with fresh envelopes."""
        if not self.stream or self.resolve is None:
            return
        where = self.resolve(name)
        if where is None:
            return
        try:
            with socket.create_connection(where) as out:
                out.sendall(TCP + struct.pack("<i", len("/yarp312/stateExt:o") + 1) + b"/yarp312/stateExt:o\0")
                _read(out, 8)
                seq = 0
                while not self._stop.is_set():
                    payload = self.stream[seq % len(self.stream)]
                    out.sendall(_message(_port_command(f"{seq} {time.time():.6f}"), payload))
                    _read(out, 8)
                    seq += 1
                    self.streamed = seq
                    time.sleep(0.02)
        except (ConnectionError, OSError):
            pass
