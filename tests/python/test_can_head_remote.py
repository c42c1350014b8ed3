# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The head's CAN driver from outside, every piece its own process: `robogene server`, `robogene
can-sim` simulating the three boards on a virtual bus, `robogene dev --device robogene_can --from
drivers/can/generated/head.ini --bus virtual:...` serving them, and a remote_controlboard client in
another process (this one, or the paper's program). Each test first runs against `robogene dev
--device test_motor --axes 6`, then unchanged against the CAN head: every joint through a position
move and a velocity move with the encoders tracking (the Python client, encoders by RPC and on
state:o), and the paper's section 3.3 program (the C++ client, encoders from stateExt:o). The
clients cannot tell the two apart."""
from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

import pytest

import paper_program

import robogene
from robogene.dev import ControlMode, IControlMode, IEncoders, IPositionControl, IVelocityControl, PolyDriver, Property

ROOT = Path(__file__).resolve().parents[2]
HEAD_INI = ROOT / "drivers" / "can" / "generated" / "head.ini"
SERVED_PORTS = ("rpc:i", "command:i", "state:o", "stateExt:o")

SPEED = 30.0          # deg/s, reference speed of the position moves
ACCELERATION = 100.0  # deg/s^2
VELOCITY = 10.0       # deg/s, the velocity moves
AT_TARGET = 0.2       # deg: a position move has arrived (the boards' PID settles to a few counts)
STILL = 0.5           # deg: how far a joint nobody commands may wander meanwhile (eye coupling)

pytestmark = pytest.mark.timeout(180)


@dataclass
class Joint:
    name: str
    low: float
    high: float


def head_joints() -> list[Joint]:
    """The head's joints and position limits, as the driver reads them from head.ini."""
    ini = Property.from_ini_file(str(HEAD_INI))
    limits = ini.find_group("LIMITS")
    return [Joint(name, float(lo), float(hi)) for name, lo, hi in
            zip(ini.find_group("GENERAL").find("axis_names"), limits.find("min"), limits.find("max"))]


JOINTS = head_joints()


def start_test_motor(procs, robogene_bin, env, name):
    return [procs.start("robogene dev test_motor", [robogene_bin, "dev", "--device", "test_motor", "--axes",
                                                    str(len(JOINTS)), "--name", name], env)]


def start_can_head(procs, robogene_bin, env, name):
    bus = "virtual:head"
    sim = procs.start("robogene can-sim", [robogene_bin, "can-sim", "--bus", bus, "--from", str(HEAD_INI)], env)
    sim.wait_for_line(rf"can-sim: 3 boards \(.*\) on {bus}")
    dev = procs.start("robogene dev robogene_can", [robogene_bin, "dev", "--device", "robogene_can", "--from",
                                                    str(HEAD_INI), "--bus", bus, "--name", name], env)
    return [sim, dev]


BACKENDS = {"test_motor": start_test_motor, "robogene_can": start_can_head}


@pytest.fixture(params=sorted(BACKENDS, reverse=True))  # test_motor first: the reference
def served_head(request, name_server, procs, robogene_bin, yarp_env, tmp_path):
    """The backend served as /head; the virtual bus lives in the test's own directory."""
    env = dict(yarp_env, ROBOGENE_CAN_DIR=str(tmp_path / "can"))
    started = BACKENDS[request.param](procs, robogene_bin, env, "/head")
    started[-1].wait_for_line(r"serving on ", timeout=30, stream="err")
    return request.param, started


class Client:
    """remote_controlboard /client -> /head, plus /client/state:i connected to /head/state:o."""

    def __init__(self, network: robogene.Network, server: str):
        self.device = PolyDriver(Property.from_dict({"device": "remote_controlboard", "remote": "/head",
                                                     "local": "/client", "server": server}))
        assert self.device.is_valid(), self.device.last_error
        self.enc = self.device.view(IEncoders)
        self.pos = self.device.view(IPositionControl)
        self.vel = self.device.view(IVelocityControl)
        self.mode = self.device.view(IControlMode)
        self.state = robogene.BufferedPort("/client/state:i", policy=robogene.BufferPolicy.LATEST_ONLY,
                                           network=network)
        network.connect("/head/state:o", "/client/state:i")

    def encoders(self) -> list[float]:
        values = self.enc.getEncoders()
        assert values is not None and len(values) == len(JOINTS), values
        return values

    def streamed(self) -> list[float]:
        """The first state:o message published after this call (the encoders as a YARP Vector)."""
        self.state.read(timeout=0)  # drop what is already queued
        message = self.state.read(timeout=2)
        assert message is not None, "no message on /head/state:o within 2 s"
        return [value.as_float() for value in message]

    def close(self) -> None:
        self.state.close()
        self.device.close()


def wait_for(what: str, ok, seconds: float) -> None:
    deadline = time.monotonic() + seconds
    while not ok():
        assert time.monotonic() < deadline, f"{what} within {seconds} s"
        time.sleep(0.01)


def position_move(client: Client, j: int, target: float) -> None:
    """Moves joint j to target: the encoder travels there at about the reference speed, without
    overshooting, and stops there; no other joint moves."""
    name = JOINTS[j].name
    before = client.encoders()
    distance = abs(target - before[j])
    assert client.pos.setRefSpeed(j, SPEED) and client.pos.setRefAcceleration(j, ACCELERATION), name
    start = time.monotonic()
    assert client.pos.positionMove(j, target), name
    # A board keeps the target in encoder counts: within half a count (1/245 deg on vergence).
    assert client.pos.getTargetPosition(j) == pytest.approx(target, abs=0.01), name
    assert client.mode.getControlMode(j) == ControlMode.POSITION, name
    trail = []
    deadline = start + distance / SPEED + 5.0
    while True:
        now = client.encoders()
        trail.append(now[j])
        for k, value in enumerate(now):
            if k != j:
                assert abs(value - before[k]) < STILL, f"{JOINTS[k].name} moved while {name} did: {value}"
        if abs(now[j] - target) < AT_TARGET and client.pos.checkMotionDone(j):
            break
        assert time.monotonic() < deadline, f"{name} did not reach {target} (encoders {trail[-5:]})"
        time.sleep(0.01)
    elapsed = time.monotonic() - start
    assert elapsed > 0.8 * distance / SPEED, f"{name} moved {distance} deg in {elapsed} s, faster than {SPEED} deg/s"
    direction = 1.0 if target > before[j] else -1.0
    between = [v for v in trail if 1.0 < direction * (v - before[j]) < distance - 1.0]
    assert len(between) >= 5, f"{name} jumped rather than moved: {trail}"
    assert all(direction * (v - target) < AT_TARGET for v in trail), f"{name} overshot {target}: {trail}"
    assert all(direction * (b - a) > -AT_TARGET for a, b in zip(trail, trail[1:])), f"{name} went back: {trail}"
    # Still there a moment later, and the stream says the same as the RPC.
    time.sleep(0.2)
    assert client.enc.getEncoder(j) == pytest.approx(target, abs=AT_TARGET), name
    assert client.streamed() == pytest.approx(client.encoders(), abs=AT_TARGET), name


def velocity_move(client: Client, j: int, speed: float) -> None:
    """Runs joint j at `speed`: the encoder advances at that rate, then stops when told to."""
    name = JOINTS[j].name
    assert client.vel.setRefAcceleration(j, ACCELERATION), name
    assert client.vel.velocityMove(j, speed), name
    # The move travels on the command port, which has no reply (as YARP's): wait for it to act.
    wait_for(f"{name} in velocity mode", lambda: client.mode.getControlMode(j) == ControlMode.VELOCITY, 2.0)
    time.sleep(0.3)  # past the ramp (0.1 s at the reference acceleration)
    t0, p0 = time.monotonic(), client.enc.getEncoder(j)
    time.sleep(0.8)
    t1, p1 = time.monotonic(), client.enc.getEncoder(j)
    rate = (p1 - p0) / (t1 - t0)
    assert rate == pytest.approx(speed, rel=0.25), f"{name} ran at {rate} deg/s, commanded {speed}"
    assert client.enc.getEncoderSpeed(j) == pytest.approx(speed, rel=0.25), name
    assert client.vel.velocityMove(j, 0.0), name
    time.sleep(0.3)
    first = client.enc.getEncoder(j)
    time.sleep(0.3)
    assert client.enc.getEncoder(j) == pytest.approx(first, abs=0.05), f"{name} did not stop"
    assert JOINTS[j].low <= first <= JOINTS[j].high, name


def test_a_remote_client_moves_every_joint_with_encoders_tracking(served_head, name_server, network):
    backend, started = served_head
    for port in SERVED_PORTS:
        assert network.query(f"/head/{port}") is not None, f"{backend}: /head/{port} is not registered"
    client = Client(network, name_server.address)
    try:
        assert client.pos.getAxes() == len(JOINTS)
        # The move targets are the head's: inside every joint's limits, 30 % of the way up.
        for j, joint in enumerate(JOINTS):
            position_move(client, j, joint.low + 0.3 * (joint.high - joint.low))
            velocity_move(client, j, VELOCITY)
    finally:
        client.close()
    for proc in started:
        assert proc.popen.poll() is None, f"{proc.name} died during the test\n{proc.describe()}"


def test_the_paper_section_3_3_program_runs_unchanged(served_head, robogene_bin, yarp_env):
    """The C++ remote_controlboard (encoders from stateExt:o, the velocity move on command:i) in the
    paper's program: joint 0 moves towards 40 deg at 5 deg/s, joint 1 runs at 5 deg/s."""
    paper_program.run_against(robogene_bin, yarp_env, "/head", 1.5)
