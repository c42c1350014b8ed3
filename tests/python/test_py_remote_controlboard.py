# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""remote_controlboard opened from Python reads the encoders (positions, speeds, accelerations)
from the server's stateExt:o stream while it is fresh: by RPC only once the last jointData is
0.5 s old, or for a field the server flags [fail]; and sends velocityMove(j, v) on the command
port. Against a test_motor served by ControlboardNws in this process, against the C++
`robogene dev`, and against a server of the test's own whose RPC requests are logged."""
from __future__ import annotations

import threading
import time

import pytest

from robogene import Bottle, BufferedPort, Network, Port, RpcClient, RpcServer
from robogene.dev import (ControlboardNws, ControlboardServer, DeviceDriver, IEncoders, ISimulationClock,
                          IVelocityControl, PolyDriver, Property)

# How old the last jointData may be before remote_controlboard reads by RPC (kStateTimeout in
# runtime/devices/src/dev/nws/remote_controlboard.cpp, YARP's rule).
STATE_TIMEOUT = 0.5

pytestmark = pytest.mark.timeout(60)


def remote(name_server, remote_name: str, **extra) -> PolyDriver:
    config = {"device": "remote_controlboard", "remote": remote_name, "local": "/pyclient",
              "server": name_server.address, **extra}
    device = PolyDriver(Property.from_dict(config))
    assert device.is_valid(), device.last_error
    return device


def readings(enc) -> tuple:
    """Every encoder reading, all axes and axis 1 alone."""
    return (enc.getEncoders(), enc.getEncoderSpeeds(), enc.getEncoderAccelerations(),
            enc.getEncoder(1), enc.getEncoderSpeed(1), enc.getEncoderAcceleration(1))


def until(what: str, done, timeout: float = 5.0) -> None:
    deadline = time.monotonic() + timeout
    while not done():
        assert time.monotonic() < deadline, f"timed out waiting for {what}"
        time.sleep(0.005)


def test_encoders_come_from_the_stream_until_it_is_half_a_second_old(name_server):
    network = Network(name_server.address)
    with PolyDriver(Property.from_dict({"device": "test_motor", "axes": 2, "clock": "manual"})) as motor:
        device, clock = motor.view(IEncoders), motor.view(ISimulationClock)
        served = Property.from_dict({"name": "/pymotors", "server": name_server.address})
        with ControlboardNws(motor.view(DeviceDriver), served), remote(name_server, "/pymotors") as client:
            enc = client.view(IEncoders)
            # Axis 1 mid-ramp (2.5 deg/s, 50 deg/s^2): the client soon reads what the device reads.
            assert motor.view(IVelocityControl).velocityMove(1, 5.0) and clock.advance(0.05)
            streamed = readings(device)
            assert streamed[4] == pytest.approx(2.5) and streamed[5] == pytest.approx(50.0)
            until("the client to read the device", lambda: readings(enc) == streamed)
            time.sleep(0.15)  # RPC gives the same: let a few periods of the stream (0.02 s) come

            # Without the stream the device moves on, but the client keeps the last jointData for
            # 0.5 s: these readings cannot have come by RPC.
            network.disconnect("/pymotors/stateExt:o", "/pyclient/stateExt:i")
            cut = time.monotonic()
            assert clock.advance(1.0)  # cruising at 5 deg/s, no acceleration
            moved = readings(device)
            assert moved != streamed
            assert readings(enc) == streamed
            assert time.monotonic() - cut < 0.4, "too slow to see the stream fresh"

            # Then it is stale, and every reading comes by RPC.
            time.sleep(max(0.0, cut + STATE_TIMEOUT + 0.1 - time.monotonic()))
            assert readings(enc) == moved
            assert enc.getEncoder(2) is None  # no axis 2, stream or not


def test_encoders_from_the_cpp_server_stream(name_server, procs, robogene_bin, yarp_env):
    dev = procs.start("robogene dev", [robogene_bin, "dev", "--device", "test_motor", "--axes", "2", "--clock",
                                       "manual", "--name", "/motors"], yarp_env)
    dev.wait_for_line(r"serving on ", stream="err")
    network = Network(name_server.address)
    with remote(name_server, "/motors") as client, \
            RpcClient(server="/motors/rpc:i", network=network) as other:
        enc = client.view(IEncoders)
        assert other.call(Bottle.from_text("[set] [encs] (7.0 8.0)")).to_text() == "[ok]"
        until("the client to read [set] [encs]", lambda: enc.getEncoders() == [7.0, 8.0])
        time.sleep(0.15)
        network.disconnect("/motors/stateExt:o", "/pyclient/stateExt:i")
        cut = time.monotonic()
        assert other.call(Bottle.from_text("[set] [encs] (9.0 10.0)")).to_text() == "[ok]"
        assert enc.getEncoders() == [7.0, 8.0] and enc.getEncoder(1) == 8.0  # from the stream
        assert time.monotonic() - cut < 0.4, "too slow to see the stream fresh"
        time.sleep(max(0.0, cut + STATE_TIMEOUT + 0.1 - time.monotonic()))
        assert enc.getEncoders() == [9.0, 10.0] and enc.getEncoder(1) == 10.0  # by RPC


class LoggedServer:
    """A control board server of the test's own: RPC answered by the generated dispatch over a
    test_motor and logged, a command port that records what it gets, and a stateExt:o the test
    writes by hand."""

    def __init__(self, network: Network):
        self.motor = PolyDriver(Property.from_dict({"device": "test_motor", "axes": 2, "clock": "manual"}))
        self.device = self.motor.view(IEncoders)
        dispatch = ControlboardServer(self.motor.view(DeviceDriver))
        self.requests, self.commands = [], []
        self.lock = threading.Lock()

        def answer(request, info):
            with self.lock:
                self.requests.append(request.to_text())
            return dispatch.respond(request)

        def command(message, info):
            with self.lock:
                self.commands.append(message.to_text())
            dispatch.command(message)

        self.rpc = RpcServer("/fake/rpc:i", answer, network=network)
        self.command = BufferedPort("/fake/command:i", network=network)
        self.command.on_read(command)
        self.state = Port("/fake/stateExt:o", network=network)

    def asked(self, word: str) -> list:
        with self.lock:
            return [r for r in self.requests if word in r.split()]

    def close(self) -> None:
        for port in (self.state, self.command, self.rpc):
            port.close()
        self.motor.close()


@pytest.fixture
def fake(name_server):
    server = LoggedServer(Network(name_server.address))
    yield server
    server.close()


JOINT_DATA = ("(7.0 8.0) [ok] (99.0 99.0) [fail] (0.5 0.25) [ok] " + "(0.0 0.0) [fail] " * 6 +
              "(0 0) [fail] (0 0) [fail]")


def test_no_encoder_request_while_the_stream_is_fresh_and_fields_flagged_fail_go_by_rpc(name_server, fake):
    assert fake.device.setEncoders([1.0, 2.0])
    with remote(name_server, "/fake", carrier="tcp") as client:
        enc = client.view(IEncoders)

        def streamed() -> bool:
            fake.state.write(Bottle.from_text(JOINT_DATA))
            return enc.getEncoders() == [7.0, 8.0]
        until("the first jointData", streamed)
        before = len(fake.asked("[encs]"))  # asked by RPC until the first jointData came
        for _ in range(20):
            fake.state.write(Bottle.from_text(JOINT_DATA))
            assert enc.getEncoders() == [7.0, 8.0] and enc.getEncoder(0) == 7.0
            assert enc.getEncoderAccelerations() == [0.5, 0.25] and enc.getEncoderAcceleration(1) == 0.25
            time.sleep(0.01)
        assert len(fake.asked("[encs]")) == before
        assert fake.asked("[enc]") == fake.asked("[eacs]") == fake.asked("[eac]") == []
        # Speeds are flagged [fail]: they come by RPC, from the device.
        assert enc.getEncoderSpeeds() == [0.0, 0.0] and enc.getEncoderSpeed(1) == 0.0
        assert fake.asked("[esps]") == ["[get] [esps]"] and fake.asked("[esp]") == ["[get] [esp] 1"]

        # Malformed jointData (one axis, or not jointData at all) is ignored: once the last good
        # one is stale, the encoders come by RPC.
        time.sleep(STATE_TIMEOUT + 0.1)
        for _ in range(5):
            fake.state.write(Bottle.from_text("(7.0) [ok]"))
            fake.state.write(Bottle.from_text(" ".join(["(7.0) [ok]"] * 9 + ["(0) [ok]"] * 2)))
        time.sleep(0.1)
        assert enc.getEncoders() == [1.0, 2.0]
        assert fake.asked("[encs]")[-1:] == ["[get] [encs]"]


def test_velocity_moves_go_on_the_command_port(name_server, fake):
    with remote(name_server, "/fake", carrier="tcp") as client:
        ivel = client.view(IVelocityControl)
        assert ivel.velocityMove(1, 2.5)
        until("the command", lambda: fake.commands == ["([vmo] 1) (2.5)"])
        assert fake.motor.view(IVelocityControl).getRefVelocity(1) == 2.5
        assert fake.asked("[vmo]") == []  # not by RPC
        assert not ivel.velocityMove(2, 1.0)  # no axis 2
        assert not ivel.velocityMove(0, float("nan"))
        assert fake.commands == ["([vmo] 1) (2.5)"]
