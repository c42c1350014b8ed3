# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The http carrier against YARP's own: the same browser requests sent to a `yarp read` port and
to a `robogene read` port deliver the same bottles to both readers, and both answer `data=` with
the port's page. (Calls differ on purpose: YARP answers them with bare text, we with HTTP/1.1.)"""
import socket
import time

import pytest

import interop_net

pytestmark = pytest.mark.timeout(120)

REQUESTS = ["data=hello+there", "get/axes", "set/pos/1/30.5?x=1"]


def get(host, port, path):
    """The whole response: YARP answers calls with the reply text alone, no status line."""
    with socket.create_connection((host, port), timeout=5) as s:
        s.sendall(f"GET /{path} HTTP/1.1\r\nHost: {host}\r\n\r\n".encode())
        s.settimeout(0.5)
        data = b""
        deadline = time.monotonic() + 3
        try:
            while time.monotonic() < deadline and (chunk := s.recv(65536)) and len(data) < 1 << 20:
                data += chunk
        except TimeoutError:
            pass  # YARP keeps a call's connection open after its answer
    return data.decode("utf-8", "replace")


def test_browser_requests_reach_yarp_and_our_readers_alike(yarpserver, yarp, ours, net):
    net.env["ROBOGENE_HTTP_WRITES"] = "1"  # off by default in ours (docs/security.md), always on in YARP
    readers = {"/interop/yr": yarp.read("/interop/yr"), "/interop/or": ours.read("/interop/or")}
    for name in readers:
        c = interop_net.query(net.ns_port, name)
        for path in REQUESTS:
            body = get(c.host, c.port, path)
            if path.startswith("data="):
                assert f"<h1>yarp port {name}</h1>" in body, body
    got = {name: proc.wait_data(len(REQUESTS), 10) for name, proc in readers.items()}
    assert got["/interop/or"] == got["/interop/yr"], got
    assert got["/interop/yr"][1] == 'get axes (REQUEST_URI "get/axes")'
