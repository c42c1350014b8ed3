# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""A real control board's streaming output (yarpdev fakeMotionControl: /state:o, a Vector with an
envelope every 20 ms) read by our tools over tcp and udp, next to `yarp read` on the same port."""
import pytest

pytestmark = pytest.mark.timeout(120)


@pytest.mark.parametrize("connector", ["yarp", "robogene"])
@pytest.mark.parametrize("carrier", ["tcp", "udp"])
def test_state_port_of_a_yarp_control_board_reaches_our_reader(connector, carrier, yarpserver, yarp, ours):
    yarp.fake_motors("/interop/motors", joints=4)
    theirs = yarp.read("/interop/yr")
    mine = ours.read("/interop/or")
    tool = yarp if connector == "yarp" else ours
    for reader in ("/interop/yr", "/interop/or"):
        done = tool.cmd("connect", "/interop/motors/state:o", reader, carrier)
        assert done.returncode == 0, done
    yarp_lines = theirs.wait_data(5, 15)
    our_lines = mine.wait_data(5, 15)
    assert len(yarp_lines[0].split()) == 4, yarp_lines[0]
    # The fake board holds still, so every sample is the same vector on both sides.
    assert set(our_lines) == set(yarp_lines) == {yarp_lines[0]}
