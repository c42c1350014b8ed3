# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Finding the name server with no yarp.conf, over the multicast fallback (224.2.1.1 at the port
$YARP_PORT_RANGE names): `yarp detect` finds `robogene server`, `robogene detect` finds yarpserver,
and both servers list the same `fallback` registration."""
import socket

import pytest

from interop_tools import RobogeneTools, YarpTools

pytestmark = pytest.mark.timeout(120)


@pytest.fixture
def private_group(net):
    """A group port of this test's own, so that no other name server on the machine answers."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        net.env["YARP_PORT_RANGE"] = str(s.getsockname()[1])
    return net.env["YARP_PORT_RANGE"]


@pytest.mark.parametrize("server_side", ["yarp", "robogene"])
def test_each_detect_finds_the_other_server(server_side, private_group, procs, net):
    yarp, ours = YarpTools(procs, net), RobogeneTools(procs, net)
    (yarp if server_side == "yarp" else ours).server()
    listing = (yarp if server_side == "yarp" else ours).cmd("name", "list").stdout.decode()
    assert f"registration name fallback ip 224.2.1.1 port {private_group} type mcast" in listing
    (net.base / "config" / "yarp.conf").unlink()
    expected = f"/root is available at ip 127.0.0.1 port {net.ns_port}"
    client = ours if server_side == "yarp" else yarp
    done = client.cmd("detect", "--write", *(["--ip", "127.0.0.1"] if client is ours else []))
    assert done.returncode == 0, done.stderr.decode()
    assert expected in done.stdout.decode()
    assert (net.base / "config" / "yarp.conf").read_text().split() == ["127.0.0.1", str(net.ns_port), "yarp"]
