# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""YARP 3.5's PID offset, enable, disable and reset requests across implementations: YARP's
remote_controlboard (in yarpdev, re-served as a proxy) switching the PIDs of `robogene dev
--device test_motor`, and our remote_controlboard, C++ (behind our controlBoard_nws_yarp) and
Python (in this process), switching those of YARP's controlboardwrapper2 over fakeMotionControl.
fakeMotionControl starts with every PID off, keeps the enable flags, accepts reset and offset, but
does not show an offset in getPid: the offset is checked only on test_motor."""
import re

import pytest

import interop_net as net_
from interop_peer import robogene_bin
from robogene.dev import IPidControl, PidType, PolyDriver, Property

pytestmark = pytest.mark.timeout(120)


def responses(proc, count, timeout=15):
    proc.wait_until(f"{count} responses", lambda: sum(l.startswith("Response: ") for l in proc.stdout) >= count,
                    timeout)
    return [l[len("Response: "):] for l in proc.stdout if l.startswith("Response: ")]


class Asker:
    """Requests typed at an rpc tool, one at a time, with their replies."""

    def __init__(self, proc):
        self.proc, self.count = proc, 0

    def __call__(self, request: str) -> str:
        self.proc.send(request)
        self.count += 1
        return responses(self.proc, self.count)[-1]


def start_robogene_dev(procs, net, *args):
    dev = procs.start("robogene dev", [robogene_bin(), "dev", *args], net.env)
    dev.wait_output(r"serving on ", 15)
    return dev


def test_yarps_remote_controlboard_switches_the_pids_of_robogene_dev(yarpserver, yarp, ours, procs, net):
    start_robogene_dev(procs, net, "--device", "test_motor", "--axes", "2", "--name", "/interop/motors")
    mine = Asker(ours.rpc("/interop/motors/rpc:i"))
    assert mine("[set] [pos] 1 30.0") == "[ok]"  # axis 1 runs its position loop
    proxy = yarp.dev("--device", "remote_controlboard", "--remote", "/interop/motors", "--local", "/interop/client",
                     "--name", "/interop/proxy")
    proxy.wait_output(r"Port /interop/proxy/rpc:i active at ", 30)
    net_.wait_registered(net.ns_port, "/interop/proxy/rpc:i", 15)
    theirs = Asker(yarp.rpc("/interop/proxy/rpc:i"))

    assert theirs("[get] [pid] [ena] [pos] 1") == "[is] [pid] 1 [ok]"  # YARP's client reads our bool
    assert theirs("[set] [pid] [off] [vel] 0 2.5") == "[ok]"
    assert mine("[get] [pid] [pid] [vel] 0") == "[is] [pid] (0.0 0.0 0.0 0.0 0.0 2.5 0.0 0.0 0.0 0.0) [ok]"
    assert theirs("[set] [pid] [dis] [pos] 1") == "[ok]"
    assert theirs("[get] [pid] [ena] [pos] 1") == "[is] [pid] 0 [ok]"
    # test_motor freed axis 1 and will not run its position loop until it is enabled again.
    assert re.fullmatch(r"\[is\] 1 \[idl\] \[tsta\] \d+ \S+ \[ok\]", mine("[get] [icmd] [cmod] 1"))
    assert mine("[set] [pos] 1 -30.0") == "[fail]"
    assert theirs("[set] [pid] [ena] [pos] 1") == "[ok]"
    assert mine("[get] [pid] [ena] [pos] 1") == "[is] [pid] 1 [ok]"
    assert mine("[set] [pos] 1 -30.0") == "[ok]"  # 6 s at the reference speed of 10 deg/s
    assert mine("[get] [pid] [err] [pos] 1") != "[is] [pid] 0.0 [ok]"
    assert theirs("[set] [pid] [res] [pos] 1") == "[ok]"  # the move ends where the axis is
    reply = mine("[get] [pid] [err] [pos] 1")
    assert reply == "[is] [pid] 0.0 [ok]", reply
    # test_motor has no current loop: YARP's client reports the refusal.
    assert theirs("[set] [pid] [dis] [cur] 0") == "[fail]"


def test_our_cpp_remote_controlboard_switches_the_pids_of_yarps_control_board(yarpserver, yarp, ours, procs, net):
    yarp.fake_motors("/interop/motors", joints=2)
    start_robogene_dev(procs, net, "--device", "controlBoard_nws_yarp", "--subdevice", "remote_controlboard",
                       "--remote", "/interop/motors", "--local", "/interop/ours", "--name", "/interop/ourproxy")
    mine = Asker(ours.rpc("/interop/ourproxy/rpc:i"))
    assert mine("[get] [pid] [ena] [pos] 1") == "[is] [pid] 0 [ok]"  # fakeMotionControl starts off
    assert mine("[set] [pid] [ena] [pos] 1") == "[ok]"
    assert mine("[get] [pid] [ena] [pos] 1") == "[is] [pid] 1 [ok]"
    assert mine("[set] [pid] [off] [pos] 1 2.5") == "[ok]"
    assert mine("[set] [pid] [res] [vel] 0") == "[ok]"
    assert mine("[set] [pid] [ena] [trq] 0") == "[ok]"
    assert mine("[set] [pid] [dis] [trq] 0") == "[ok]"

    # The switches reached YARP's device: read back through YARP's own rpc.
    theirs = Asker(yarp.rpc("/interop/motors/rpc:i"))
    assert theirs("[get] [pid] [ena] [pos] 1") == "[is] [pid] 1 [ok]"
    assert theirs("[get] [pid] [ena] [trq] 0") == "[is] [pid] 0 [ok]"
    assert theirs("[get] [pid] [ena] [pos] 0") == "[is] [pid] 0 [ok]"


def test_our_python_remote_controlboard_switches_the_pids_of_yarps_control_board(yarpserver, yarp, net):
    yarp.fake_motors("/interop/motors", joints=2)
    with PolyDriver(Property.from_dict({"device": "remote_controlboard", "remote": "/interop/motors",
                                        "local": "/interop/py", "server": net.server_arg})) as client:
        assert client.is_valid(), client.last_error
        pid = client.view(IPidControl)
        assert pid.isPidEnabled(PidType.VELOCITY, 0) is False
        assert pid.enablePid(PidType.VELOCITY, 0)
        assert pid.isPidEnabled(PidType.VELOCITY, 0) is True
        assert pid.setPidOffset(PidType.POSITION, 1, -1.5)
        assert pid.resetPid(PidType.POSITION, 1)
        assert pid.enablePid(PidType.CURRENT, 1) and pid.disablePid(PidType.CURRENT, 1)
        assert pid.isPidEnabled(PidType.CURRENT, 1) is False
        assert pid.isPidEnabled(PidType.VELOCITY, 5) is None  # no joint 5: YARP answers [fail]
    theirs = Asker(yarp.rpc("/interop/motors/rpc:i"))
    assert theirs("[get] [pid] [ena] [vel] 0") == "[is] [pid] 1 [ok]"
