# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Administrative messages over binary tcp (PortCommand 'a'), as `yarp admin rpc` sends them: our
ports must answer exactly as YARP's own ports in the same situation (a writer connected to a reader)."""
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


@pytest.mark.parametrize("role", ["writer", "reader"])
def test_our_ports_answer_admin_requests_like_yarp_ports(role, yarpserver, yarp, ours, net):
    yarp.read("/interop/yr")
    yarp.write("/interop/yw", "/interop/yr")
    ours.read("/interop/or")
    ours.write("/interop/ow", "/interop/or")
    interop_net.wait_connection(net.ns_port, "/interop/ow", "/interop/or")
    results = {}
    for side, (w, r) in (("yarp", ("/interop/yw", "/interop/yr")), ("robogene", ("/interop/ow", "/interop/or"))):
        requests = [q.replace("/R", r).replace("/W", w) for q in REQUESTS]
        answers = ask(yarp, w if role == "writer" else r, requests)
        results[side] = [a.replace(f'"{w}"', '"/W"').replace(f'"{r}"', '"/R"') for a in answers]
    assert results["robogene"] == results["yarp"]
