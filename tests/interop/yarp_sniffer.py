# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""A minimal tcp-carrier input port in pure Python that records the exact messages a peer sends it:
it answers the 8-byte header and sender name, reads each indexed message, splits off the 8-byte
PortCommand and acks. Used to capture the bytes real YARP puts on the wire."""
from __future__ import annotations

import queue
import socket
import struct
import threading
from dataclasses import dataclass

TCP_ACK_HEADER = b"YA\xe4\x1e\x00\x00RP"
INDEX_HEADER = b"YA\x0a\x00\x00\x00RP"
ACK = b"YA\x00\x00\x00\x00RP"


@dataclass
class Message:
    command: bytes   # the 8-byte PortCommand (or the command string, for ch 0)
    payload: bytes   # everything after it: the serialised object


class ProtocolError(Exception):
    pass


def _read_exact(conn: socket.socket, n: int, what: str, offset: int) -> bytes:
    data = b""
    while len(data) < n:
        chunk = conn.recv(n - len(data))
        if not chunk:
            raise ProtocolError(f"connection closed at byte {offset + len(data)} while reading {what}")
        data += chunk
    return data


class Sniffer:
    def __init__(self):
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(4)
        self.port = self.sock.getsockname()[1]
        self.messages: "queue.Queue[Message | Exception]" = queue.Queue()
        self.sender = None
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self) -> None:
        conn, _ = self.sock.accept()
        offset = 0
        try:
            with conn:
                header = _read_exact(conn, 8, "carrier header", offset); offset += 8
                if header != TCP_ACK_HEADER:
                    raise ProtocolError(f"expected the tcp carrier header {TCP_ACK_HEADER!r}, got {header!r}")
                (name_len,) = struct.unpack("<i", _read_exact(conn, 4, "sender name length", offset)); offset += 4
                self.sender = _read_exact(conn, name_len, "sender name", offset).rstrip(b"\0").decode(); offset += name_len
                conn.sendall(b"YA" + struct.pack("<i", self.port) + b"RP")
                while True:
                    index = _read_exact(conn, 8, "index header", offset); offset += 8
                    if index != INDEX_HEADER:
                        raise ProtocolError(f"byte {offset - 8}: expected index header, got {index!r}")
                    counts = _read_exact(conn, 10, "block counts", offset); offset += 10
                    n_in, n_out = counts[0], counts[1]
                    lengths = struct.unpack(f"<{n_in + n_out}i",
                                            _read_exact(conn, 4 * (n_in + n_out), "block lengths", offset))
                    offset += 4 * (n_in + n_out)
                    body = _read_exact(conn, sum(lengths), "message body", offset); offset += sum(lengths)
                    command, payload = body[:8], body[8:]
                    if command[4:5] == b"~" and command[5] == 0:
                        (text_len,) = struct.unpack("<i", command[:4])
                        command, payload = payload[:text_len], payload[text_len:]
                    conn.sendall(ACK)
                    self.messages.put(Message(command, payload))
                    if command == b"q\0":
                        return
        except Exception as e:  # handed to the reader of self.messages, which reports it
            self.messages.put(e)

    def next(self, timeout: float = 5.0) -> Message:
        item = self.messages.get(timeout=timeout)
        if isinstance(item, Exception):
            raise item
        return item

    def close(self) -> None:
        self.sock.close()
