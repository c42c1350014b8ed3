# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""YARP's own remote_controlboard drives the head's CAN driver: `robogene can-sim` simulates the
boards on a virtual bus, `robogene dev --device robogene_can --from head.ini` serves them, and
YARP's yarpdev opens a remote_controlboard to it (re-served as /interop/proxy, as in
test_control_board_devices.py). Every joint makes a position move and one joint a velocity move
(which YARP streams on command:o); YARP reads the encoders back from our stateExt:o."""
import re
import time
from pathlib import Path

import pytest

import interop_net as net_
from interop_peer import ROOT, robogene_bin
from robogene.dev import Property

pytestmark = pytest.mark.timeout(180)

HEAD_INI = ROOT / "drivers" / "can" / "generated" / "head.ini"
AT_TARGET = 0.2  # deg


def head_limits() -> list[tuple[float, float]]:
    limits = Property.from_ini_file(str(HEAD_INI)).find_group("LIMITS")
    return [(float(lo), float(hi)) for lo, hi in zip(limits.find("min"), limits.find("max"))]


class Rpc:
    """A `yarp rpc` session: send a request, wait for its reply."""

    def __init__(self, proc):
        self.proc, self.sent = proc, 0

    def call(self, request: str, timeout: float = 15) -> str:
        self.proc.send(request)
        self.sent += 1
        self.proc.wait_until(f"a reply to {request!r}", lambda: len(self.replies()) >= self.sent, timeout)
        return self.replies()[self.sent - 1]

    def replies(self) -> list:
        return [l[len("Response: "):] for l in self.proc.stdout if l.startswith("Response: ")]

    def value(self, request: str, reply: str = "") -> str:
        reply = reply or self.call(request)
        m = re.fullmatch(r"\[is\] \S+ (.+) \[tsta\] \d+ \S+ \[ok\]", reply)
        assert m, f"{request}: {reply}"
        return m.group(1)

    def encoders(self, timeout: float = 10) -> list:
        """YARP's client answers [get] [encs] from the last stateExt:o message, and [fail] while it
        holds no fresh one (before the first, or when udp messages come late on a loaded machine)."""
        deadline = time.monotonic() + timeout
        while (reply := self.call("[get] [encs]")) == "[fail]":
            assert time.monotonic() < deadline, f"no fresh encoders from stateExt:o within {timeout} s"
            time.sleep(0.05)
        return [float(x) for x in self.value("[get] [encs]", reply).strip("()").split()]


def test_yarps_remote_controlboard_moves_the_simulated_can_head(yarpserver, yarp, procs, net):
    env = dict(net.env, ROBOGENE_CAN_DIR=str(Path(net.base) / "can"))
    sim = procs.start("robogene can-sim", [robogene_bin(), "can-sim", "--bus", "virtual:head", "--from",
                                           str(HEAD_INI)], env)
    sim.wait_output(r"can-sim: 3 boards .* on virtual:head", 15)
    dev = procs.start("robogene dev", [robogene_bin(), "dev", "--device", "robogene_can", "--from", str(HEAD_INI),
                                       "--bus", "virtual:head", "--name", "/interop/head"], env)
    dev.wait_output(r"robogene_can serving on ", 30)
    proxy = yarp.dev("--device", "remote_controlboard", "--remote", "/interop/head", "--local", "/interop/client",
                     "--name", "/interop/proxy")
    proxy.wait_output(r"Port /interop/proxy/rpc:i active at ", 30)
    net_.wait_registered(net.ns_port, "/interop/proxy/rpc:i", 15)
    theirs = Rpc(yarp.rpc("/interop/proxy/rpc:i"))

    limits = head_limits()
    assert theirs.value("[get] [axes]") == str(len(limits))
    start = theirs.encoders()  # waits for the first stateExt:o message to arrive
    targets = [lo + 0.3 * (hi - lo) for lo, hi in limits]
    for j, target in enumerate(targets):
        assert theirs.call(f"[set] [vel] {j} 30.0") == "[ok]"
        assert theirs.call(f"[set] [pos] {j} {target!r}") == "[ok]"

    # YARP's client reads the encoders from our stateExt:o: every joint passes through its move
    # and arrives at its target.
    seen = [start]
    deadline = time.monotonic() + 15
    while not all(abs(e - t) < AT_TARGET for e, t in zip(seen[-1], targets)):
        assert time.monotonic() < deadline, f"the joints did not reach {targets}: {seen[-3:]}\n{dev.describe()}"
        time.sleep(0.05)
        seen.append(theirs.encoders())
    for j, target in enumerate(targets):
        halfway = [e[j] for e in seen if 1.0 < abs(e[j] - start[j]) < abs(target - start[j]) - 1.0]
        assert halfway, f"joint {j} jumped to its target rather than moving: {[e[j] for e in seen]}"
    # Our side agrees on the targets YARP set (the boards keep them in encoder counts).
    ours = Rpc(procs.start("robogene rpc", [robogene_bin(), "rpc", "/interop/head/rpc:i"], env))
    for j, target in enumerate(targets):
        assert float(ours.value(f"[get] [pos] {j}")) == pytest.approx(target, abs=0.01)

    # A velocity move on neck_yaw (YARP 3.5's wrapper takes velocity moves of all joints only, and
    # its client streams them on command:o): the encoder advances at that rate, then stops.
    assert theirs.call("[set] [vmos] (0.0 0.0 10.0 0.0 0.0 0.0)") == "[ok]"
    time.sleep(0.4)
    t0, p0 = time.monotonic(), theirs.encoders()[2]
    time.sleep(1.0)
    t1, p1 = time.monotonic(), theirs.encoders()[2]
    assert (p1 - p0) / (t1 - t0) == pytest.approx(10.0, rel=0.3), (p0, p1, t1 - t0)
    assert theirs.call("[set] [vmos] (0.0 0.0 0.0 0.0 0.0 0.0)") == "[ok]"
    time.sleep(0.4)
    stopped = theirs.encoders()[2]
    time.sleep(0.3)
    assert theirs.encoders()[2] == pytest.approx(stopped, abs=0.05)

    for proc in (sim, dev, proxy):
        assert proc.running(), proc.describe()
