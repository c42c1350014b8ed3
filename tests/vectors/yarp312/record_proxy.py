# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""A transparent TCP relay on loopback that logs every byte each side sends, to capture what a real
YARP talks without touching it: register the relay's address under a port name of its own
(`yarp name register /px/rpc:i tcp 127.0.0.1 <listen>`) and point the YARP client at that name.

usage: record_proxy.py <listen port> <target port> <log file>
The log has one JSON object a line: {"conn": "<listen port>.<n>", "dir": "c2s"|"s2c", "hex": "..."},
in the order the relay saw them (several relays may share a log). fixtures_from_log.py turns it into the fixtures of this directory."""
from __future__ import annotations

import json
import socket
import sys
import threading


def relay(conn_id: str, src: socket.socket, dst: socket.socket, direction: str, log, lock) -> None:
    try:
        while True:
            data = src.recv(65536)
            if not data:
                break
            with lock:
                log.write(json.dumps({"conn": conn_id, "dir": direction, "hex": data.hex()}) + "\n")
                log.flush()
            dst.sendall(data)
    except OSError:
        pass
    finally:
        for s in (src, dst):
            try:
                s.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass


def main() -> int:
    listen_port, target_port, log_path = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    server.bind(("127.0.0.1", listen_port))
    server.listen(8)
    lock = threading.Lock()
    with open(log_path, "a") as log:
        conn_id = 0
        while True:
            client, _ = server.accept()
            upstream = socket.create_connection(("127.0.0.1", target_port))
            conn_id += 1
            for src, dst, direction in ((client, upstream, "c2s"), (upstream, client, "s2c")):
                threading.Thread(target=relay, args=(f"{listen_port}.{conn_id}", src, dst, direction, log, lock),
                                 daemon=True).start()


if __name__ == "__main__":
    sys.exit(main())
