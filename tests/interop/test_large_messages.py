# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Messages bigger than one read, one block and one udp datagram (65507 bytes): a real YARP port
writes them to `yarp read` (always over tcp: YARP 3.5.0's own udp reader garbles multi-datagram
messages, see docs/interop.md) and to `robogene read` over the carrier under test, and both must
print the same text. And the other way: our writer to `yarp read`."""
import random

import pytest

pytestmark = pytest.mark.timeout(120)


def big_texts():
    rng = random.Random(1234)
    blob = "{" + " ".join(str(rng.randrange(256)) for _ in range(70000)) + "}"
    doubles = "(" + " ".join(f"{rng.uniform(-1e6, 1e6):.6f}" for _ in range(9000)) + ")"
    strings = " ".join(f"s{i}" for i in range(20000))
    return [blob, doubles, strings]


@pytest.mark.parametrize("carrier", ["tcp", "udp"])
def test_large_yarp_messages_reach_both_readers_identically(carrier, yarpserver, yarp, ours):
    theirs = yarp.read("/interop/yr")
    mine = ours.read("/interop/or")
    writer = yarp.python("writer", "yarp_stamped_writer.py", "/interop/sw")
    writer.wait_output(r"^ready$", 15)
    for target, how in (("/interop/yr", "tcp"), ("/interop/or", carrier)):
        assert yarp.cmd("connect", "/interop/sw", target, how).returncode == 0
        writer.wait_output(rf"Sending output from /interop/sw to {target} using {how}", 15)
    texts = big_texts()
    for text in texts:
        writer.send(text)
    want = theirs.wait_data(len(texts), 30)
    got = mine.wait_data(len(texts), 30)
    assert len(want[0]) > 65507
    for i, (w, g) in enumerate(zip(want, got)):
        assert g == w, f"message {i}: {len(g)} chars from robogene read vs {len(w)} from yarp read"
    assert len(got) == len(want) == len(texts)


def test_large_messages_from_our_writer_to_yarp_read(yarpserver, yarp, ours):
    theirs = yarp.read("/interop/yr")
    writer = ours.write("/interop/ow", "/interop/yr")
    theirs.wait_output(r"Receiving input from /interop/ow to /interop/yr using tcp", 15)
    texts = big_texts()
    for text in texts:
        writer.send(text)
    got = theirs.wait_data(len(texts), 30)
    # YARP's own rendering of what it received must equal its rendering of the text we sent.
    yarp_echo = yarp.read("/interop/yr2")
    yarp_writer = yarp.write("/interop/yw", "/interop/yr2")
    for text in texts:
        yarp_writer.send(text)
    want = yarp_echo.wait_data(len(texts), 30)
    assert [len(l) for l in got] == [len(l) for l in want]
    assert got == want
