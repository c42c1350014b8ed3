# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Control boards across implementations, device to device: our remote_controlboard (through the
paper's section 3.3 program) driving YARP's controlboardwrapper2 over fakeMotionControl, and
YARP's remote_controlboard (in yarpdev, re-served as a proxy) driving our `robogene dev`."""
import os
import re

import pytest

import interop_net as net_
from interop_peer import robogene_bin

pytestmark = pytest.mark.timeout(120)


def responses(proc, count, timeout=15):
    proc.wait_until(f"{count} responses", lambda: sum(l.startswith("Response: ") for l in proc.stdout) >= count,
                    timeout)
    return [l[len("Response: "):] for l in proc.stdout if l.startswith("Response: ")]


def value_of(reply: str) -> str:
    """The value of `[is] [what] <value> [tsta] n t [ok]`."""
    m = re.fullmatch(r"\[is\] \S+ (.+) \[tsta\] \d+ \S+ \[ok\]", reply)
    assert m, reply
    return m.group(1)


def paper_program() -> str:
    return os.path.join(os.path.dirname(robogene_bin()), "paper_section_3_3")


def start_robogene_dev(procs, net, *args):
    dev = procs.start("robogene dev", [robogene_bin(), "dev", *args], net.env)
    dev.wait_output(r"serving on ", 15)
    return dev


def assert_never_asked_for_fingerprints(yarp_server):
    """YARP's control board logs "received an unknown request after a VOCAB_GET: rgif" for our
    fingerprint request: it must never get one (docs/interop.md, the server's identity)."""
    lines = yarp_server.stdout + yarp_server.stderr
    assert not any("rgif" in line for line in lines), yarp_server.describe()


def test_our_remote_controlboard_drives_yarps_control_board(yarpserver, yarp, ours, procs, net):
    motors = yarp.fake_motors("/interop/motors", joints=4)
    program = procs.start("paper_section_3_3", [
        paper_program(), "--device", "remote_controlboard", "--remote", "/interop/motors",
        "--local", "/interop/paper", "--seconds", "2"], net.env)
    program.wait_output(r"^t=0\.00 s", 15)
    # While it runs, its encoder stream comes from YARP's stateExt:o over udp, as YARP's client does.
    listed = yarp.cmd("admin", "rpc", "/interop/motors/stateExt:o", stdin="[list] [out] /interop/paper/stateExt:i\n")
    assert b"(carrier udp)" in listed.stdout, listed
    program.wait_until("exit", lambda: not program.running(), 20)
    assert "(exited with 0," in program.describe(), program.describe()
    last = program.stdout[-1]
    # fakeMotionControl jumps to a position target: joint 0 reads 40 at once.
    assert re.fullmatch(r"t=\S+ s  joint 0:  40\.000 deg  joint 1: +\S+ deg", last), program.describe()

    # Every call reached the YARP device: read back through YARP's own rpc.
    rpc = yarp.rpc("/interop/motors/rpc:i")
    for request in ("[get] [acc] 0", "[get] [vel] 0", "[get] [pos] 0", "[get] [acc] 1", "[get] [vmo] 1"):
        rpc.send(request)
    acc0, vel0, pos0, acc1, vmo1 = (value_of(r) for r in responses(rpc, 5))
    assert (acc0, vel0, pos0, acc1) == ("100.0", "5.0", "40.0", "100.0")
    assert vmo1 == "5.0"  # velocityMove(1, 5) travelled on /interop/paper/command:o over udp
    assert_never_asked_for_fingerprints(motors)


def test_yarps_remote_controlboard_drives_robogene_dev(yarpserver, yarp, ours, procs, net):
    start_robogene_dev(procs, net, "--device", "test_motor", "--axes", "4", "--name", "/interop/motors")
    # YARP's yarpdev opens its remote_controlboard (checks [prot], asks [get] [axes], connects our
    # stateExt:o to its stateExt:i over udp) and serves it again as /interop/proxy.
    proxy = yarp.dev("--device", "remote_controlboard", "--remote", "/interop/motors", "--local", "/interop/client",
                     "--name", "/interop/proxy")
    proxy.wait_output(r"Port /interop/proxy/rpc:i active at ", 30)
    net_.wait_registered(net.ns_port, "/interop/proxy/rpc:i", 15)

    theirs = yarp.rpc("/interop/proxy/rpc:i")
    theirs.send("[get] [axes]")
    # YARP's wrapper turns the all-joints call into a group one: ([vmog] 4 (0 1 2 3)) (...) on command:o.
    theirs.send("[set] [vmos] (0.0 5.0 0.0 0.0)")
    theirs.send("[set] [vel] 0 50.0")
    theirs.send("[set] [pos] 0 30.0")
    axes, vmos, set_vel, set_pos = responses(theirs, 4)
    assert value_of(axes) == "4"
    assert (vmos, set_vel, set_pos) == ("[ok]", "[ok]", "[ok]")

    mine = ours.rpc("/interop/motors/rpc:i")
    mine.send("[get] [pos] 0")
    mine.send("[get] [vel] 0")
    assert [value_of(r) for r in responses(mine, 2)] == ["30.0", "50.0"]
    # The all-joints velocity move went through YARP's command:o to our command:i.
    mine.send("[get] [vmo] 1")
    assert value_of(responses(mine, 3)[2]) == "5.0"

    # YARP's client reads the encoders from our stateExt:o: they follow test_motor's motion.
    sent = [4]

    seen = []

    def encoders_reach(condition) -> bool:
        """Asks YARP's client for the encoders; it answers [fail] while it holds no fresh stateExt:o
        message (before the first, or when udp messages come late on a loaded machine): not yet."""
        theirs.send("[get] [encs]")
        sent[0] += 1
        reply = responses(theirs, sent[0])[-1]
        if reply == "[fail]":
            return False
        seen.append([float(x) for x in value_of(reply).strip("()").split()])
        return condition(seen[-1])

    theirs.wait_until("both joints moving", lambda: encoders_reach(lambda e: min(e[:2]) > 0.0), 10)
    theirs.wait_until("joint 0 at its target", lambda: encoders_reach(lambda e: abs(e[0] - 30.0) < 1e-6), 10)
    last = seen[-1]
    assert len(last) == 4 and last[1] > 0.0 and last[2] == last[3] == 0.0, last

    # YARP's client asks whether every axis is done ([get] [dons]) and reads one int, as its own server sends:
    # not while joint 1 runs, and once every axis is stopped. (It read our old per-axis list as "not done".)
    def all_done() -> str:
        theirs.send("[get] [dons]")
        sent[0] += 1
        return value_of(responses(theirs, sent[0])[-1])
    assert all_done() == "0"
    theirs.send("[set] [stos]")
    sent[0] += 1
    assert responses(theirs, sent[0])[-1] == "[ok]"
    theirs.wait_until("YARP's client sees every axis done", lambda: all_done() == "1", 10)


PID_POS_1 = "(6000.0 500.0 5.0 1333.0 1333.0 0.0 8.0 0.5 -0.5 1.0)"


def pid_reply(reply: str) -> str:
    """The value of `[is] [pid] <value> [ok]`: YARP's PID replies carry no [tsta] stamp."""
    m = re.fullmatch(r"\[is\] \[pid\] (.+) \[ok\]", reply)
    assert m, reply
    return m.group(1)


def test_our_remote_controlboard_reads_pids_and_torques_from_yarps_control_board(yarpserver, yarp, ours, procs,
                                                                                 net):
    motors = yarp.fake_motors("/interop/motors", joints=2)
    # Our remote_controlboard, served again by our controlBoard_nws_yarp as /interop/ourproxy (as the
    # YARP side does below with yarpdev), so that requests typed at our rpc go through its client.
    start_robogene_dev(procs, net, "--device", "controlBoard_nws_yarp", "--subdevice", "remote_controlboard",
                       "--remote", "/interop/motors", "--local", "/interop/ours", "--name", "/interop/ourproxy")
    mine = ours.rpc("/interop/ourproxy/rpc:i")
    mine.send("[set] [pid] [pids] [pos] ((1.5 2 3 4 5 6 7 8 9 10) (6000 500 5 1333 1333 0 8 0.5 -0.5 1))")
    mine.send("[get] [pid] [pid] [pos] 1")
    mine.send("[get] [pid] [pids] [pos]")
    mine.send("[set] [pid] [pid] [trq] 0 (1 2 3 4 5 6 7 8 9 10)")
    mine.send("[get] [pid] [pid] [trq] 0")
    mine.send("[get] [pid] [out] [vel] 1")  # fakeMotionControl's outputs: 1.2 + 10 j for velocity
    mine.send("[get] [pid] [err] [trq] 0")  # and its errors: 0.4 for torque
    mine.send("[get] [torq] [trqs]")
    mine.send("[get] [torq] [axes]")
    (set_pids, pid_1, pids, set_trq, trq_0, out_1, err_0, trqs, axes) = responses(mine, 9)
    assert (set_pids, set_trq) == ("[ok]", "[ok]")
    assert pid_reply(pid_1) == PID_POS_1
    assert pid_reply(pids) == f"((1.5 2.0 3.0 4.0 5.0 6.0 7.0 8.0 9.0 10.0) {PID_POS_1})"
    assert pid_reply(trq_0) == "(1.0 2.0 3.0 4.0 5.0 6.0 7.0 8.0 9.0 10.0)"
    assert float(pid_reply(out_1)) == 11.2 and float(pid_reply(err_0)) == 0.4
    assert value_of(trqs) == "(0.0 0.0)" and value_of(axes) == "2"

    # The gains reached YARP's device: read back through YARP's own rpc.
    rpc = yarp.rpc("/interop/motors/rpc:i")
    rpc.send("[get] [pid] [pid] [pos] 1")
    assert pid_reply(responses(rpc, 1)[0]) == PID_POS_1
    assert_never_asked_for_fingerprints(motors)


def test_yarps_remote_controlboard_reads_pids_and_torques_from_robogene_dev(yarpserver, yarp, ours, procs, net):
    start_robogene_dev(procs, net, "--device", "test_motor", "--axes", "2", "--name", "/interop/motors")
    mine = ours.rpc("/interop/motors/rpc:i")
    mine.send("[set] [pid] [pid] [pos] 1 (6000 500 5 1333 1333 0 8 0.5 -0.5 1)")
    mine.send("[set] [torq] [ref] 0 0.5")  # axis 0 under torque control
    assert responses(mine, 2) == ["[ok]", "[ok]"]
    proxy = yarp.dev("--device", "remote_controlboard", "--remote", "/interop/motors", "--local", "/interop/client",
                     "--name", "/interop/proxy")
    proxy.wait_output(r"Port /interop/proxy/rpc:i active at ", 30)
    net_.wait_registered(net.ns_port, "/interop/proxy/rpc:i", 15)

    theirs = yarp.rpc("/interop/proxy/rpc:i")
    theirs.send("[get] [pid] [pid] [pos] 1")
    theirs.send("[get] [pid] [pids] [pos]")
    theirs.send("[set] [pid] [pid] [vel] 0 (1 2 3 4 5 6 7 8 9 10)")
    theirs.send("[get] [torq] [ref] 0")
    pid_1, pids, set_vel, ref_0 = responses(theirs, 4)
    assert pid_reply(pid_1) == PID_POS_1
    assert pid_reply(pids) == f"((0.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0) {PID_POS_1})"
    assert set_vel == "[ok]"
    assert value_of(ref_0) == "0.5"

    # YARP's setPid reached test_motor.
    mine.send("[get] [pid] [pid] [vel] 0")
    assert pid_reply(responses(mine, 3)[2]) == "(1.0 2.0 3.0 4.0 5.0 6.0 7.0 8.0 9.0 10.0)"

    # YARP's client reads torques and control modes from our stateExt:o (jointData) once it has one.
    asked = {theirs: 4, mine: 3}

    def ask(proc, request):
        proc.send(request)
        asked[proc] += 1
        return responses(proc, asked[proc])[-1]

    theirs.wait_until("the torque in jointData", lambda: ask(theirs, "[get] [torq] [trqs]").startswith(
        "[is] [torq] (0.5 0.0) [tsta] "), 10)
    assert re.fullmatch(r"\[is\] 0 \[torq\] \[tsta\] \d+ \S+ \[ok\]", ask(theirs, "[get] [icmd] [cmod] 0"))

    # YARP's client streams torque references ([dtq] j, [dtqs]) on command:o to our command:i.
    assert ask(theirs, "[set] [torq] [ref] 1 0.25") == "[ok]"
    mine.wait_until("setRefTorque(1, 0.25)", lambda: value_of(ask(mine, "[get] [torq] [ref] 1")) == "0.25", 10)
    assert ask(theirs, "[set] [torq] [refs] (0.75 1.0)") == "[ok]"
    mine.wait_until("setRefTorques", lambda: value_of(ask(mine, "[get] [torq] [refs]")) == "(0.75 1.0)", 10)
