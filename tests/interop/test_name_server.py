# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Name service interop, differentially: the same `name` script is run by {yarp, robogene} clients
against {yarpserver, robogene server}; every combination must print what `yarp name` prints against
yarpserver (server-chosen port numbers aside), and exit with the same status. On failure only the
status and that the message names the port are compared: YARP prints `[ERROR] /x not known.` on
stdout, our CLI writes its error to stderr (on purpose, see docs/interop.md)."""
import re

import pytest

import interop_net
from interop_tools import RobogeneTools, YarpTools

pytestmark = pytest.mark.timeout(120)

SCRIPT = [
    ["register", "/interop/a"],
    ["register", "/interop/b", "tcp", "127.0.0.1", "12345"],
    ["query", "/interop/b"],
    ["query", "/interop/a"],
    ["list", "/interop"],
    ["set", "/interop/b", "process", "4242"],
    ["get", "/interop/b", "process"],
    ["check", "/interop/b", "process", "4242"],
    ["unregister", "/interop/a"],
    ["query", "/interop/a"],
    ["list", "/interop"],
    ["unregister", "/interop/b"],
    ["query", "/interop/b"],
]


def tools_for(kind, procs, net):
    return YarpTools(procs, net) if kind == "yarp" else RobogeneTools(procs, net)


def run_script(client):
    """Run SCRIPT; returns [(command, exit status, stdout)] with the server-chosen port of /interop/a
    replaced by <auto> (after checking it is the same number everywhere it appears)."""
    out = []
    auto_ports = set()
    for words in SCRIPT:
        done = client.cmd("name", *words)
        text = done.stdout.decode("utf-8", "backslashreplace")
        if done.returncode != 0:
            said = text + done.stderr.decode("utf-8", "backslashreplace")
            text = f"<error naming {words[1]}>" if words[1] in said else f"<error: {said!r}>"
        for m in re.finditer(r"registration name /interop/a ip \S+ port (\d+)", text):
            auto_ports.add(m.group(1))
        text = re.sub(r"(registration name /interop/a ip \S+ port )\d+", r"\g<1><auto>", text)
        out.append((" ".join(words), done.returncode, text))
    assert len(auto_ports) == 1, f"/interop/a should keep one server-chosen port number, saw {auto_ports}"
    return out


@pytest.fixture
def reference(procs, other_net):
    """The script as real YARP runs it: `yarp name` against yarpserver."""
    yarp = YarpTools(procs, other_net)
    yarp.server()
    return run_script(yarp)


@pytest.mark.parametrize("client,server", [("yarp", "robogene"), ("robogene", "yarp"), ("robogene", "robogene")])
def test_name_commands_match_yarp(client, server, procs, net, reference):
    tools_for(server, procs, net).server()
    got = run_script(tools_for(client, procs, net))
    for (cmd, want_rc, want_out), (_, rc, out) in zip(reference, got):
        assert (rc, out) == (want_rc, want_out), f"`name {cmd}` ({client} client, {server} server)"


def test_name_list_without_prefix_lists_root(procs, net):
    RobogeneTools(procs, net).server()
    done = YarpTools(procs, net).cmd("name", "list")
    assert done.returncode == 0
    assert f"registration name /root ip 127.0.0.1 port {net.ns_port} type tcp" in done.stdout.decode()


def test_yarp_ports_talk_through_our_name_server(procs, net, yarp_bottle_vectors):
    """yarp read/write register, announce, query and unregister via robogene server only."""
    RobogeneTools(procs, net).server()
    yarp = YarpTools(procs, net)
    reader = yarp.read("/interop/yr")
    writer = yarp.write("/interop/yw", "/interop/yr")
    writer.send('1 2.5 "hi" [set]')
    assert reader.wait_data(1, 10) == ["1 2.5 hi [set]"]
    listed = yarp.cmd("name", "list").stdout.decode()
    assert "registration name /interop/yr ip 127.0.0.1" in listed and "registration name /interop/yw" in listed
    reader.stop()
    interop_net.wait_unregistered(net.ns_port, "/interop/yr", 10)


def test_our_port_registers_on_yarpserver_and_unregisters_on_exit(yarpserver, yarp, ours, net):
    reader = ours.read("/interop/or")
    done = yarp.cmd("name", "query", "/interop/or")
    assert done.returncode == 0, done
    line = done.stdout.decode().splitlines()[0]
    contact = interop_net.query(net.ns_port, "/interop/or")
    assert line == f"registration name /interop/or ip 127.0.0.1 port {contact.port} type tcp"
    interop_net.wait_listening(contact.port)
    reader.stop()
    assert not reader.running()
    interop_net.wait_unregistered(net.ns_port, "/interop/or", 10)


def test_yarp_clean_against_our_name_server(procs, net):
    """`yarp clean` lists the ports, probes each, unregisters the dead ones and asks for gc."""
    RobogeneTools(procs, net).server()
    yarp = YarpTools(procs, net)
    yarp.read("/interop/alive")
    dead_port = net.ns_port + 30          # inside our free block, nobody listens there
    assert yarp.cmd("name", "register", "/interop/dead", "tcp", "127.0.0.1", str(dead_port)).returncode == 0
    done = yarp.cmd("clean", "--timeout", "2", timeout=60)
    assert done.returncode == 0, done
    assert "* No response, removing port /interop/dead" in done.stdout.decode()
    listed = yarp.cmd("name", "list").stdout.decode()
    assert "registration name /interop/alive ip 127.0.0.1" in listed
    assert "/interop/dead" not in listed
