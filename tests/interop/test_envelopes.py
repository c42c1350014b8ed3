# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Envelopes (the `"D <seq> <time>"` PortCommand that state ports send): a real YARP port writes
stamped bottles to `yarp read ... envelope` and `robogene read --envelope` at once; both must
report the same stamps and payloads. `yarp read` prints the stamp and the bottle on two lines
(`0 1000.25 ` then the bottle), ours on one (`0 1000.25 | bottle`): see docs/interop.md."""
import pytest

pytestmark = pytest.mark.timeout(90)

PAYLOADS = ["1.0 2.0 3.0 4.0", "[ok] (1 2) x", '"with space" {1 2}']


def test_stamped_yarp_output_reaches_both_readers_with_the_same_envelopes(yarpserver, yarp, ours):
    theirs = yarp.read("/interop/yr", "envelope")
    mine = ours.read("/interop/or", "--envelope")
    writer = yarp.python("stamped writer", "yarp_stamped_writer.py", "/interop/sw")
    writer.wait_output(r"^ready$", 15)
    for target in ("/interop/yr", "/interop/or"):
        assert yarp.cmd("connect", "/interop/sw", target).returncode == 0
        writer.wait_output(rf"Sending output from /interop/sw to {target} using tcp", 15)
    for payload in PAYLOADS:
        writer.send(payload)

    yarp_lines = theirs.wait_data(2 * len(PAYLOADS), 15)
    yarp_pairs = [(yarp_lines[i].strip(), yarp_lines[i + 1]) for i in range(0, len(yarp_lines), 2)]
    our_pairs = [tuple(line.split(" | ", 1)) for line in mine.wait_data(len(PAYLOADS), 15)]
    assert yarp_pairs == [(f"{i} {1000.25 + i}", p) for i, p in enumerate(PAYLOADS)]
    assert our_pairs == yarp_pairs
