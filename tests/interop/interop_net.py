# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Small raw-socket clients the harness uses to observe both implementations the same way:
free-port search, name-server queries (the bytes real YARP clients send) and admin requests
over text_ack (what `yarp connect` does)."""
from __future__ import annotations

import random
import re
import socket
import time
from dataclasses import dataclass
from typing import Optional

LOCALHOST = "127.0.0.1"


def _port_free(port: int) -> bool:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        try:
            s.bind(("", port))  # YARP built with ACE binds 0.0.0.0, so test the wildcard address
        except OSError:
            return False
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        try:
            s.bind(("", port))
        except OSError:
            return False
    return True


def _ephemeral_low() -> int:
    try:
        with open("/proc/sys/net/ipv4/ip_local_port_range") as f:
            return int(f.read().split()[0])
    except (OSError, ValueError, IndexError):
        return 32768


def free_port_block(width: int = 40) -> int:
    """A base port P with P..P+width-1 free: a name server on P hands out P+2, P+3, ... to ports.
    Chosen below the kernel's ephemeral range, so outgoing connections cannot take them meanwhile."""
    rng = random.Random()
    top = min(_ephemeral_low(), 60000) - width
    for _ in range(200):
        base = rng.randrange(20000, top)
        if all(_port_free(base + i) for i in range(width)):
            return base
    raise RuntimeError(f"no free block of {width} ports found between 20000 and {top + width}")


@dataclass
class Contact:
    name: str
    host: str
    port: int
    carrier: str


_REGISTRATION = re.compile(r"registration name (\S+) ip (\S+) port (\d+) type (\S+)")


def name_server_request(ns_port: int, command: str, timeout: float = 5.0) -> str:
    """Send `NAME_SERVER <command>` the way YARP's NameClient does; return the text reply."""
    with socket.create_connection((LOCALHOST, ns_port), timeout=timeout) as s:
        s.sendall(f"NAME_SERVER {command}\n".encode())
        data = b""
        deadline = time.monotonic() + timeout
        while b"*** end of message" not in data and not data.rstrip().endswith(b"[ok]"):
            if time.monotonic() > deadline:
                raise TimeoutError(f"name server on port {ns_port}: no complete reply to {command!r}, got {data!r}")
            chunk = s.recv(4096)
            if not chunk:
                break
            data += chunk
    return data.decode("utf-8", "backslashreplace")


def query(ns_port: int, name: str) -> Optional[Contact]:
    reply = name_server_request(ns_port, f"query {name}")
    m = _REGISTRATION.search(reply)
    return Contact(m.group(1), m.group(2), int(m.group(3)), m.group(4)) if m else None


def wait_registered(ns_port: int, name: str, timeout: float = 10.0) -> Contact:
    deadline = time.monotonic() + timeout
    last_error = None
    while time.monotonic() < deadline:
        try:
            contact = query(ns_port, name)
            if contact is not None:
                return contact
        except OSError as e:
            last_error = e
        time.sleep(0.05)
    raise AssertionError(f"{name} not registered on the name server at port {ns_port} within {timeout} s"
                         + (f" (last error: {last_error})" if last_error else ""))


def wait_unregistered(ns_port: int, name: str, timeout: float = 10.0) -> None:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if query(ns_port, name) is None:
            return
        time.sleep(0.05)
    raise AssertionError(f"{name} still registered on the name server at port {ns_port} after {timeout} s")


def wait_listening(port: int, timeout: float = 10.0) -> None:
    deadline = time.monotonic() + timeout
    while True:
        try:
            socket.create_connection((LOCALHOST, port), timeout=1).close()
            return
        except OSError:
            if time.monotonic() > deadline:
                raise AssertionError(f"nothing listening on {LOCALHOST}:{port} after {timeout} s") from None
            time.sleep(0.05)


def admin_text_ack(contact: Contact, bottle_text: str, timeout: float = 5.0) -> str:
    """One administrative request over text_ack, exactly as `yarp connect` sends it; returns the
    reply line(s) before `<ACK>`."""
    with socket.create_connection((contact.host, contact.port), timeout=timeout) as s:
        f = s.makefile("rwb")
        f.write(b"CONNACK /interop_admin\r\n")
        f.flush()
        welcome = f.readline()
        if not welcome.startswith(b"Welcome"):
            raise AssertionError(f"{contact.name}: expected 'Welcome ...' after CONNACK, got {welcome!r}")
        f.write(b"a\r\n" + bottle_text.encode() + b"\r\n")
        f.flush()
        lines = []
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            line = f.readline()
            if not line:
                raise AssertionError(f"{contact.name}: connection closed before <ACK>; got {lines!r}")
            line = line.decode("utf-8", "backslashreplace").rstrip("\r\n")
            if line == "<ACK>":
                return "\n".join(lines)
            lines.append(line)
        raise AssertionError(f"{contact.name}: no <ACK> within {timeout} s; got {lines!r}")


def wait_connection(ns_port: int, src: str, dst: str, timeout: float = 10.0) -> None:
    """Wait until port src reports an output to dst ([list] [out] over admin)."""
    deadline = time.monotonic() + timeout
    last = ""
    while time.monotonic() < deadline:
        contact = query(ns_port, src)
        if contact is not None:
            try:
                last = admin_text_ack(contact, "[list] [out]")
                if re.search(rf'(^|[\s"(]){re.escape(dst)}($|[\s")])', last):
                    return
            except (OSError, AssertionError) as e:
                last = str(e)
        time.sleep(0.05)
    raise AssertionError(f"no connection {src} -> {dst} within {timeout} s; last [list] [out] reply: {last!r}")
