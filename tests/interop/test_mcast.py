# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""mcast across implementations (YARP 3.5.0 builds it into libYARP_os): a YARP writer streaming
to two of our readers through one multicast group, and our writer streaming to two `yarp read`s,
with the group allocated by yarpserver or by our name server. Each reader must get each line
exactly once. The connections are made the usual way, by `yarp connect` / `robogene connect`
asking the writer for an `mcast://` output."""
import time

import pytest

import interop_net

pytestmark = pytest.mark.timeout(120)

LINES = ["[ok] 1 (2.5 x)", "tick 2 3.5", "(nested list) last"]  # no int before a string: yarp read hides such ints


def wait_input(ns_port, reader, writer, timeout=10.0):
    """Our readers list an mcast input once they have joined the group."""
    deadline = time.monotonic() + timeout
    listed = ""
    while time.monotonic() < deadline:
        listed = interop_net.admin_text_ack(interop_net.query(ns_port, reader), "[list] [in]")
        if writer in listed:
            return
        time.sleep(0.05)
    raise AssertionError(f"{reader} has no input from {writer}: {listed!r}")


@pytest.mark.parametrize("server", ["yarpserver", "robogene server"])
def test_yarp_writer_streams_to_our_readers_over_mcast(server, yarp, ours, net):
    (yarp.server() if server == "yarpserver" else ours.server())
    readers = [ours.read("/interop/or1"), ours.read("/interop/or2")]
    writer = yarp.write("/interop/yw")
    for r in ("/interop/or1", "/interop/or2"):
        done = yarp.cmd("connect", "/interop/yw", r, "mcast")
        assert done.returncode == 0, done
        wait_input(net.ns_port, r, "/interop/yw")
    for line in LINES:
        writer.send(line)
    for proc in readers:
        assert proc.wait_data(len(LINES), 10) == LINES
    time.sleep(0.3)  # a second copy of any line would have arrived by now
    for proc in readers:
        assert proc.data == LINES


@pytest.mark.parametrize("server", ["yarpserver", "robogene server"])
def test_our_writer_streams_to_yarp_readers_over_mcast(server, yarp, ours, net):
    (yarp.server() if server == "yarpserver" else ours.server())
    readers = [yarp.read("/interop/yr1"), yarp.read("/interop/yr2")]
    writer = ours.write("/interop/ow")
    for r in ("/interop/yr1", "/interop/yr2"):
        done = ours.cmd("connect", "/interop/ow", r, "mcast")
        assert done.returncode == 0, done
        readers[0 if r.endswith("1") else 1].wait_output(rf"Receiving input from /interop/ow to {r} using mcast", 15)
    groups = [l for l in interop_net.name_server_request(net.ns_port, "list").splitlines()
              if l.endswith("type mcast") and "name /tmp/port/" in l]  # yarpserver also lists its "fallback"
    assert len(groups) == 1, groups
    for line in LINES:
        writer.send(line)
    for proc in readers:
        assert proc.wait_data(len(LINES), 10) == LINES
    # Our writer leaving ends the YARP readers' inputs out of band ([del]), as a YARP writer does.
    writer.close_stdin()
    for proc, r in zip(readers, ("/interop/yr1", "/interop/yr2")):
        proc.wait_output(rf"Removing input from /interop/ow to {r}", 15)
