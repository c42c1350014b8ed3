# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""remote_controlboard opened from Python (robogene.dev, in this test process) against YARP 3.5's
control board server over fakeMotionControl: it reads the encoders from YARP's stateExt:o (udp)
while that is fresh and by RPC once it is 0.5 s old, and sends velocityMove on YARP's command:i
(YARP's server does not take it by RPC)."""
import re
import time

import pytest

import robogene
from robogene.dev import IEncoders, IPositionControl, IVelocityControl, PolyDriver, Property

# How old the last jointData may be before remote_controlboard reads by RPC (kStateTimeout in
# runtime/devices/src/dev/nws/remote_controlboard.cpp, YARP's rule).
STATE_TIMEOUT = 0.5

pytestmark = pytest.mark.timeout(120)


def until(what: str, done, timeout: float = 10.0) -> None:
    deadline = time.monotonic() + timeout
    while not done():
        assert time.monotonic() < deadline, f"timed out waiting for {what}"
        time.sleep(0.01)


def responses(proc, count, timeout=15):
    proc.wait_until(f"{count} responses", lambda: sum(l.startswith("Response: ") for l in proc.stdout) >= count,
                    timeout)
    return [l[len("Response: "):] for l in proc.stdout if l.startswith("Response: ")]


@pytest.mark.parametrize("wrapper", ["controlboardwrapper2", "controlBoard_nws_yarp"])
def test_python_remote_controlboard_reads_yarps_stream(yarpserver, yarp, net, procs, wrapper):
    server = yarp.dev("--device", wrapper, "--subdevice", "fakeMotionControl", "--name", "/interop/motors",
                      "--GENERAL::Joints", "2")
    for suffix in ("rpc:i", "command:i", "stateExt:o"):
        server.wait_output(rf"Port /interop/motors/{suffix} active at ", 30)
    network = robogene.Network(net.server_arg)
    with PolyDriver(Property.from_dict({"device": "remote_controlboard", "remote": "/interop/motors",
                                        "local": "/interop/py", "server": net.server_arg})) as client:
        assert client.is_valid(), client.last_error
        enc, ipos = client.view(IEncoders), client.view(IPositionControl)
        listed = network.admin("/interop/motors/stateExt:o", robogene.Bottle.from_text("[list] [out] /interop/py/stateExt:i"))
        assert "(carrier udp)" in listed.to_text(), listed.to_text()

        # fakeMotionControl jumps to a position target.
        assert ipos.positionMove(0, 25.0)
        until("joint 0 at 25", lambda: enc.getEncoder(0) == 25.0)
        time.sleep(0.15)  # RPC says the same: let a few jointData messages come
        assert len(enc.getEncoderSpeeds()) == 2 and len(enc.getEncoderAccelerations()) == 2

        # Cut the stream: YARP's device jumps again, the client keeps the last jointData for 0.5 s.
        network.disconnect("/interop/motors/stateExt:o", "/interop/py/stateExt:i")
        cut = time.monotonic()
        assert ipos.positionMove(0, 40.0)
        assert enc.getEncoder(0) == 25.0 and enc.getEncoders()[0] == 25.0  # from the stream
        assert time.monotonic() - cut < 0.4, "too slow to see the stream fresh"
        time.sleep(max(0.0, cut + STATE_TIMEOUT + 0.1 - time.monotonic()))
        assert enc.getEncoder(0) == 40.0 and enc.getEncoders()[0] == 40.0  # by RPC

        # velocityMove(1, 5) travels on command:i: YARP's RPC would refuse [set] [vmo].
        assert client.view(IVelocityControl).velocityMove(1, 5.0)
        rpc = yarp.rpc("/interop/motors/rpc:i")
        rpc.send("[set] [vmo] 1 6.0")
        assert responses(rpc, 1) == ["[fail]"]
        asked = [1]

        def ref_velocity() -> str:
            rpc.send("[get] [vmo] 1")
            asked[0] += 1
            return responses(rpc, asked[0])[-1]
        until("YARP's reference velocity of joint 1", lambda: re.fullmatch(
            r"\[is\] \[vmo\] 5\.0 \[tsta\] \d+ \S+ \[ok\]", ref_velocity()) is not None)
    assert network.query("/interop/py/stateExt:i") is None
