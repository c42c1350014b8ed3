# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The everyday tools across implementations: ping, ls, read/write with the peer named on the
command line, and `yarp rpc` to a port of ours that replies (the name server's /root)."""
import re

import pytest

import interop_net
from interop_tools import RobogeneTools, YarpTools

pytestmark = pytest.mark.timeout(120)


def normalise(text, names):
    for old, new in names.items():
        text = text.replace(f'"{old}"', f'"{new}"')
    return re.sub(r"tcp://127\.0\.0\.1:\d+/", "tcp://127.0.0.1:<port>/", text)


def test_yarp_ping_describes_our_ports_as_it_describes_its_own(yarpserver, yarp, ours):
    yarp.read("/interop/yr")
    yarp.write("/interop/yw", "/interop/yr")
    ours.read("/interop/or")
    ours.write("/interop/ow", "/interop/or")
    interop_net.wait_connection(yarp.net.ns_port, "/interop/ow", "/interop/or")
    for theirs, mine in (("/interop/yw", "/interop/ow"), ("/interop/yr", "/interop/or")):
        want = yarp.cmd("ping", theirs)
        got = yarp.cmd("ping", mine)
        assert got.returncode == want.returncode == 0, (want, got)
        rename = {"/interop/yw": "/w", "/interop/ow": "/w", "/interop/yr": "/r", "/interop/or": "/r"}
        assert normalise(got.stdout.decode(), rename) == normalise(want.stdout.decode(), rename)


def test_robogene_ping_a_yarp_port(yarpserver, yarp, ours, net):
    yarp.read("/interop/yr")
    done = ours.cmd("ping", "/interop/yr")
    assert done.returncode == 0, done
    assert re.match(r"Port /interop/yr is alive at tcp://127\.0\.0\.1:\d+/ \(answered \[ver\] 1 2 3 in [\d.]+ ms\)",
                    done.stdout.decode()), done.stdout
    missing = ours.cmd("ping", "/interop/nobody")
    assert missing.returncode != 0 and b"/interop/nobody" in missing.stderr, missing


def test_robogene_ls_shows_connections_between_yarp_ports(yarpserver, yarp, ours):
    yarp.read("/interop/yr")
    yarp.write("/interop/yw", "/interop/yr")
    done = ours.cmd("ls", "/interop")
    assert done.returncode == 0, done
    lines = done.stdout.decode().splitlines()
    assert re.fullmatch(r"/interop/yw\s+tcp://127\.0\.0\.1:\d+/", lines[lines.index("  -> /interop/yr (tcp)") - 1])
    assert re.fullmatch(r"/interop/yr\s+tcp://127\.0\.0\.1:\d+/", lines[lines.index("  <- /interop/yw (tcp)") - 1])


def test_robogene_read_pulls_from_a_yarp_writer(yarpserver, yarp, ours):
    writer = yarp.write("/interop/yw")
    reader = ours.read("/interop/or", "/interop/yw")
    writer.wait_output(r"Sending output from /interop/yw to /interop/or using tcp", 15)
    interop_net.wait_connection(yarp.net.ns_port, "/interop/yw", "/interop/or")
    writer.send('[set] [pos] 1 30.5 "x y"')
    assert reader.wait_data(1, 10) == ['[set] [pos] 1 30.5 "x y"']


def test_yarp_read_pulls_from_our_writer(yarpserver, yarp, ours):
    writer = ours.write("/interop/ow")
    reader = yarp.read("/interop/yr", "/interop/ow")
    reader.wait_output(r"Receiving input from /interop/ow to /interop/yr using tcp", 15)
    # The reader logs the input as soon as the handshake is done, a moment before our writer has
    # finished the admin [add] and counts the connection among its outputs.
    interop_net.wait_connection(yarp.net.ns_port, "/interop/ow", "/interop/yr")
    writer.send("(1 2.5) {7 8}")
    assert reader.wait_data(1, 10) == ["(1 2.5) {7 8}"]


@pytest.mark.parametrize("request_text", ["bot query /root", "bot query /interop/x", "bot list /interop",
                                          "bot query /interop/nobody"])
def test_yarp_rpc_to_our_name_server_port(request_text, procs, net, other_net):
    """`yarp rpc /root` is a binary tcp RPC ('d', reply bottle, ack) to a port of ours; the replies
    must be those yarpserver gives (the port number of /root aside)."""
    replies = []
    for server_kind, network in (("yarp", other_net), ("robogene", net)):
        yarp = YarpTools(procs, network)
        (yarp if server_kind == "yarp" else RobogeneTools(procs, network)).server()
        assert yarp.cmd("name", "register", "/interop/x", "tcp", "127.0.0.1", "4000").returncode == 0
        client = yarp.rpc("/root")
        client.send(request_text)
        line = client.wait_output(r"^Response: ", 10, "stdout")
        replies.append(line.replace(f"(port_number {network.ns_port})", "(port_number <ns>)"))
    assert replies[1] == replies[0]


def test_robogene_rpc_over_text_ack_to_a_yarp_echo_server(yarpserver, yarp, ours):
    yarp.echo_server("/interop/echo")
    client = ours.rpc("/interop/echo", "--carrier", "text_ack")
    client.send('[get] (1 2.5 "a b") {1 2}')
    line = client.wait_output(r"^Response: ", 10, "stdout")
    assert line == 'Response: [get] (1 2.5 "a b") {1 2}'
