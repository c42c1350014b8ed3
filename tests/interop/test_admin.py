# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Administrative messages over binary tcp (PortCommand 'a'), as `yarp admin rpc` sends them: our
ports must answer exactly as YARP's own ports in the same situation (a writer connected to a reader)."""
import re

import pytest

import interop_net

pytestmark = pytest.mark.timeout(120)

REQUESTS = ["[ver]", "[list] [out]", "[list] [in]", "[list] [out] /R", "[list] [in] /W", "[bogus]"]


def ask(yarp, port, requests):
    client = yarp.admin_rpc(port)
    answers = []
    for request in requests:
        client.send(request)
        client.wait_until(f"reply to {request}", lambda: len(client.data) > len(answers), 10)
        answers = client.data
    return answers


def start_pairs(yarp, ours, net):
    """A YARP writer connected to a YARP reader, and the same pair of ours."""
    yarp.read("/interop/yr")
    yarp.write("/interop/yw", "/interop/yr")
    ours.read("/interop/or")
    ours.write("/interop/ow", "/interop/or")
    interop_net.wait_connection(net.ns_port, "/interop/ow", "/interop/or")


@pytest.mark.parametrize("role", ["writer", "reader"])
def test_our_ports_answer_admin_requests_like_yarp_ports(role, yarpserver, yarp, ours, net):
    start_pairs(yarp, ours, net)
    results = {}
    for side, (w, r) in (("yarp", ("/interop/yw", "/interop/yr")), ("robogene", ("/interop/ow", "/interop/or"))):
        requests = [q.replace("/R", r).replace("/W", w) for q in REQUESTS]
        answers = ask(yarp, w if role == "writer" else r, requests)
        results[side] = [a.replace(f'"{w}"', '"/W"').replace(f'"{r}"', '"/R"') for a in answers]
    assert results["robogene"] == results["yarp"]


# [prop]: user properties, a connection's QoS (IP_TOS) and scheduling, and the port's own thread,
# process, platform and use. Thread and process ids, the program's path and its arguments differ
# between the two runs by nature, so they are masked; everything else must be identical.
PROP_REQUESTS = ["[prop] [get]", "[prop] [set] gain 3", "[prop] [get] gain", "[prop] [get]",
                 "[prop] [get] /PEER", "[prop] [set] /PEER (qos ((tos 32)))", "[prop] [get] /PEER",
                 "[prop] [get] /SELF", "[prop] [get] /ghost", "[prop] [frob]"]
MASKS = [(r"\((tid|pid) \d+\)", r"(\1 N)"), (r'\(name "[^"]*"\)', "(name X)"),
         (r'\(arguments "[^"]*"\)', "(arguments X)")]


@pytest.mark.parametrize("role", ["writer", "reader"])
def test_our_ports_answer_prop_requests_like_yarp_ports(role, yarpserver, yarp, ours, net):
    start_pairs(yarp, ours, net)
    results = {}
    for side, (w, r) in (("yarp", ("/interop/yw", "/interop/yr")), ("robogene", ("/interop/ow", "/interop/or"))):
        me, peer = (w, r) if role == "writer" else (r, w)
        requests = [q.replace("/PEER", peer).replace("/SELF", me) for q in PROP_REQUESTS]
        answers = ask(yarp, me, requests)
        for pattern, mask in MASKS:
            answers = [re.sub(pattern, mask, a) for a in answers]
        results[side] = [a.replace(f'"{me}"', '"/SELF"').replace(f'"{peer}"', '"/PEER"') for a in answers]
    assert results["robogene"] == results["yarp"]
    assert "(tos 32)" in results["robogene"][6]
