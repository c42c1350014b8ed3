# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Connection management across implementations: `yarp connect`/`yarp disconnect` acting on our ports
(admin [add]/[del]/[list] over text_ack) and `robogene connect`/`disconnect` acting on YARP ports."""
import pytest

import interop_net

pytestmark = pytest.mark.timeout(120)


def test_yarp_connect_and_disconnect_between_our_ports(yarpserver, yarp, ours, net):
    reader = ours.read("/interop/or")
    writer = ours.write("/interop/ow")
    assert yarp.cmd("connect", "/interop/ow", "/interop/or").returncode == 0
    interop_net.wait_connection(net.ns_port, "/interop/ow", "/interop/or")
    writer.send("before 1")
    assert reader.wait_data(1, 10) == ["before 1"]

    done = yarp.cmd("disconnect", "/interop/ow", "/interop/or")
    assert done.returncode == 0, done
    listed = interop_net.admin_text_ack(interop_net.query(net.ns_port, "/interop/ow"), "[list] [out]")
    assert "/interop/or" not in listed
    writer.send("while disconnected")

    assert yarp.cmd("connect", "/interop/ow", "/interop/or").returncode == 0
    interop_net.wait_connection(net.ns_port, "/interop/ow", "/interop/or")
    writer.send("after 2")
    assert reader.wait_data(2, 10) == ["before 1", "after 2"]


def test_yarp_connect_reports_a_missing_target_of_our_port(yarpserver, yarp, ours):
    ours.write("/interop/ow")
    done = yarp.cmd("connect", "/interop/ow", "/interop/nobody")
    assert done.returncode != 0, done


@pytest.mark.parametrize("carrier", [None, "tcp", "udp", "text"])
def test_robogene_connect_and_disconnect_between_yarp_ports(carrier, yarpserver, yarp, ours, net):
    reader = yarp.read("/interop/yr")
    writer = yarp.write("/interop/yw")
    args = ["connect", "/interop/yw", "/interop/yr"] + ([carrier] if carrier else [])
    done = ours.cmd(*args)
    assert done.returncode == 0, done
    used = carrier or "tcp"
    reader.wait_output(rf"Receiving input from /interop/yw to /interop/yr using {used}", 15)
    writer.send("[ok] 1 (2.5 x)")
    assert reader.wait_data(1, 10) == ["[ok] 1 (2.5 x)"]

    done = ours.cmd("disconnect", "/interop/yw", "/interop/yr")
    assert done.returncode == 0, done
    reader.wait_output(r"Removing input from /interop/yw to /interop/yr", 15)
    listed = interop_net.admin_text_ack(interop_net.query(net.ns_port, "/interop/yw"), "[list] [out]")
    assert "/interop/yr" not in listed


def test_robogene_connect_reports_an_unknown_port(yarpserver, yarp, ours):
    yarp.write("/interop/yw")
    done = ours.cmd("connect", "/interop/yw", "/interop/nobody")
    assert done.returncode != 0 and b"/interop/nobody" in done.stderr, done
