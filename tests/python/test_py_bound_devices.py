# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The C++ device layer bound in robogene._core (robogene.dev.core), in both directions:
C++ drivers (test_motor, fake_grabber) opened and moved from Python through PolyDriver, and
devices written in Python, registered in the same C++ factory, served by the C++ servers and
driven by C++ programs (the paper's section 3.3 program, the C++ remote clients)."""
from __future__ import annotations

import gc
import re
import subprocess
import sys
import threading
import weakref
from pathlib import Path

import pytest

from robogene import Bottle, Network, RpcClient
from robogene.dev.core import (ConfigError, ControlboardNws, ControlMode, DeviceDriver, DriverFactory,
                               IControlMode, IEncoders, IFrameGrabberImage, ImageRgb, INetworkWrapper,
                               IPositionControl, ISimulationClock, IVelocityControl, Pid, PolyDriver,
                               Property, wrapper_for)

pytestmark = pytest.mark.timeout(60)


def test_a_cpp_test_motor_is_opened_and_moved_from_python():
    with PolyDriver(Property.from_dict({"device": "test_motor", "axes": 2, "clock": "manual"})) as motor:
        assert motor.is_valid(), motor.last_error
        ipos, ienc = motor.view(IPositionControl), motor.view(IEncoders)
        clock = motor.view(ISimulationClock)
        assert motor.view(IFrameGrabberImage) is None
        assert ienc.getAxes() == 2
        assert ipos.setRefSpeed(0, 5.0) and ipos.setRefAcceleration(0, 100.0)
        assert ipos.positionMove(0, 40.0)
        assert ipos.checkMotionDone(0) is False
        assert clock.advance(1.0)
        # 5 deg/s after a 0.05 s ramp at 100 deg/s^2: 5 * 1.0 - 5 * 5 / (2 * 100) deg.
        assert ienc.getEncoder(0) == pytest.approx(5.0 - 0.125, abs=1e-9)
        assert ienc.getEncoder(7) is None  # no such axis: the C++ false is None
        assert clock.advance(10.0)
        assert ienc.getEncoders() == [40.0, 0.0]
        assert ipos.checkMotionDone(0) is True
        assert motor.view(IControlMode).getControlModes() == [ControlMode.POSITION, ControlMode.POSITION]


def test_a_cpp_fake_grabber_gives_frames_to_python():
    with PolyDriver(Property.from_dict({"device": "fake_grabber", "width": 32, "height": 24})) as camera:
        assert camera.is_valid(), camera.last_error
        frames = camera.view(IFrameGrabberImage)
        assert (frames.width(), frames.height()) == (32, 24)
        first, second = frames.getImage(), frames.getImage()
        assert (first.width, first.height, len(first.pixels)) == (32, 24, 32 * 24 * 3)
        assert first.pixels != second.pixels  # the pattern moves from frame to frame
        assert camera.view(IEncoders) is None


def test_a_view_used_after_close_or_reopen_reaches_a_closed_device_not_freed_memory():
    motor = PolyDriver(Property.from_dict({"device": "test_motor", "axes": 2, "clock": "manual"}))
    ipos, ienc = motor.view(IPositionControl), motor.view(IEncoders)
    assert ipos.positionMove(0, 1.0)
    assert motor.close() and not motor.is_valid()
    # The closed test_motor, kept in memory while its views live, refuses as a closed one does.
    assert ienc.getAxes() is None and ipos.positionMove(0, 2.0) is False
    assert motor.open(Property.from_dict({"device": "test_motor", "axes": 3}))
    assert ienc.getAxes() is None and motor.view(IEncoders).getAxes() == 3
    del motor
    gc.collect()
    assert ipos.getTargetPosition(0) is None  # the view keeps its PolyDriver, and so the device


def test_an_unknown_device_and_a_bad_key_are_named():
    device = PolyDriver()
    assert not device.open("no_such_motor")
    assert "no_such_motor" in device.last_error and "test_motor" in device.last_error
    assert not device.open(Property.from_dict({"device": "test_motor", "axes": "many"}, "motor.ini"))
    assert "motor.ini['axes']" in device.last_error and "'axes'" in device.last_error
    assert device.view(IEncoders) is None


class RecordingBoard(DeviceDriver, IEncoders, IPositionControl, IVelocityControl):
    """A control board in Python whose joints jump: a position move puts the joint at its
    target, a velocity move at 100 times the speed (so a reader can tell it from test_motor).
    It records every call C++ makes, from whichever server thread makes it."""

    def __init__(self):
        super().__init__()
        self.calls = []
        self.lock = threading.Lock()
        self.positions = []

    def _record(self, *call):
        with self.lock:
            self.calls.append(call)

    def open(self, config):
        self.positions = [0.0] * config.get_int("axes", 2, 1, 16)
        self._record("open", config.get_string("name", ""))
        return True

    def close(self):
        self._record("close")
        return True

    def getAxes(self):
        return len(self.positions)

    def getEncoder(self, j):
        return self.positions[j] if 0 <= j < len(self.positions) else None

    def getEncoders(self):
        with self.lock:
            return list(self.positions)

    def getEncoderSpeeds(self):
        return [0.0] * len(self.positions)

    def getEncoderAccelerations(self):
        return [0.0] * len(self.positions)

    def positionMove(self, j, ref):
        self._record("positionMove", j, ref)
        with self.lock:
            self.positions[j] = ref
        return True

    def setRefSpeed(self, j, sp):
        self._record("setRefSpeed", j, sp)
        return True

    def setRefAcceleration(self, j, acc):
        self._record("setRefAcceleration", j, acc)
        return True

    def velocityMove(self, j, sp):
        self._record("velocityMove", j, sp)
        with self.lock:
            self.positions[j] = 100.0 * sp
        return True

    def checkMotionDone(self, j):
        raise RuntimeError("this board cannot tell")


@pytest.fixture
def recording_board():
    """RecordingBoard in the C++ factory as `recording_board`; the instances it made."""
    made = []

    def create():
        board = RecordingBoard()
        made.append(board)
        return board

    factory = DriverFactory.instance()
    if not factory.has("recording_board"):
        factory.add("recording_board", "a Python control board that records its calls", lambda: _creator[0]())
    _creator[0] = create
    return made


_creator = [None]  # the factory keeps its creator for the process; each test points it at its own list


def run_section_3_3(robogene_bin: str, env: dict, remote: str) -> tuple[float, float]:
    """The C++ section 3.3 program against `remote`: the joints it printed last."""
    program = Path(robogene_bin).parent / "paper_section_3_3"
    run = subprocess.run([str(program), "--device", "remote_controlboard", "--remote", remote, "--local", "/paper",
                          "--seconds", "0.5"], capture_output=True, text=True, env=env, timeout=30)
    assert run.returncode == 0, run.stderr
    m = re.fullmatch(r"t=\S+ s  joint 0: +(\S+) deg  joint 1: +(\S+) deg", run.stdout.splitlines()[-1])
    assert m, run.stdout
    return float(m.group(1)), float(m.group(2))


def test_a_python_device_is_served_by_the_cpp_server_to_a_cpp_program(recording_board, name_server, robogene_bin,
                                                                       yarp_env):
    config = Property.from_dict({"device": "controlBoard_nws_yarp", "subdevice": "recording_board", "axes": 2,
                                 "name": "/pyboard", "server": name_server.address})
    with PolyDriver(config) as served:
        assert served.is_valid(), served.last_error
        assert served.view(INetworkWrapper).port_names() == ["/pyboard/rpc:i", "/pyboard/command:i",
                                                             "/pyboard/state:o", "/pyboard/stateExt:o"]
        joint0, joint1 = run_section_3_3(robogene_bin, yarp_env, "/pyboard")
        # What the C++ program printed is the Python board's behaviour, not a simulated motor's.
        assert (joint0, joint1) == (40.0, 500.0)
        board, = recording_board
        calls = list(board.calls)
        assert calls[0] == ("open", "/pyboard")
        for call in (("setRefAcceleration", 0, 100.0), ("setRefSpeed", 0, 5.0), ("positionMove", 0, 40.0),
                     ("setRefAcceleration", 1, 100.0), ("velocityMove", 1, 5.0)):
            assert call in calls
        with RpcClient(server="/pyboard/rpc:i", network=Network(name_server.address)) as client:
            assert client.call(Bottle.from_text("[get] [enc] 0")).to_text().startswith("[is] [enc] 40.0 [tsta] ")
    assert board.calls[-1] == ("close",)
    assert Network(name_server.address).query("/pyboard/rpc:i") is None


def test_a_python_device_made_in_python_is_served_directly_by_the_cpp_server(name_server):
    board = RecordingBoard()
    assert board.open(Property.from_dict({"axes": 2}))
    assert wrapper_for(board) == "controlBoard_nws_yarp"  # C++ sees its IEncoders
    with ControlboardNws() as server:
        server.open(board, Property.from_dict({"name": "/direct", "server": name_server.address}))
        with RpcClient(server="/direct/rpc:i", network=Network(name_server.address)) as client:
            assert client.call(Bottle.from_text("[set] [pos] 1 12.5")).to_text() == "[ok]"
            assert board.positions == [0.0, 12.5]
            assert client.call(Bottle.from_text("[get] [axes]")).to_text().startswith("[is] [axes] 2 [tsta] ")
            # IVelocityControl came through too; ITorqueControl is not the board's: not served.
            assert client.call(Bottle.from_text("[set] [vmo] 0 2.0")).to_text() == "[ok]"
            assert client.call(Bottle.from_text("[get] [torq] [trqs]")).to_text() == "[fail]"
    assert board.positions == [200.0, 12.5]
    assert Network(name_server.address).query("/direct/rpc:i") is None


def test_a_python_method_that_raises_answers_fail_and_is_reported(recording_board, name_server):
    reported = []
    config = Property.from_dict({"device": "controlBoard_nws_yarp", "subdevice": "recording_board",
                                 "name": "/pyboard2", "server": name_server.address})
    with PolyDriver(config) as served, RpcClient(server="/pyboard2/rpc:i",
                                                  network=Network(name_server.address)) as client:
        assert served.is_valid(), served.last_error
        previous = sys.unraisablehook
        sys.unraisablehook = reported.append
        try:
            assert client.call(Bottle.from_text("[get] [don] 0")).to_text() == "[fail]"
            # A method the class does not define: NotImplementedError naming both.
            assert client.call(Bottle.from_text("[get] [pos] 0")).to_text() == "[fail]"
        finally:
            sys.unraisablehook = previous
    assert [type(r.exc_value) for r in reported] == [RuntimeError, NotImplementedError]
    assert "this board cannot tell" in str(reported[0].exc_value)
    assert "RecordingBoard implements IPositionControl but not its method getTargetPosition" in \
        str(reported[1].exc_value)


def test_a_python_device_stays_alive_while_cpp_holds_it(recording_board):
    device = PolyDriver(Property.from_dict({"device": "recording_board", "axes": 3}))
    assert device.is_valid(), device.last_error
    alive = weakref.ref(recording_board.pop())
    gc.collect()
    assert alive() is not None  # only the C++ PolyDriver refers to it now
    assert device.view(IEncoders).getEncoders() == [0.0, 0.0, 0.0]
    assert device.view(DeviceDriver) is alive()
    device.close()
    gc.collect()
    assert alive() is None


class StrictBoard(DeviceDriver, IEncoders):
    def open(self, config):
        raise ConfigError(f"{config.origin('axes')}: key 'axes': this board has exactly 4")

    def close(self):
        return True


def test_a_python_open_that_raises_config_error_is_named_by_polydriver():
    factory = DriverFactory.instance()
    if not factory.has("strict_board"):
        factory.add("strict_board", "refuses every configuration", StrictBoard)
        factory.add("not_a_device", "its creator returns a string", lambda: "motor")
    device = PolyDriver()
    assert not device.open(Property.from_dict({"device": "strict_board", "axes": 2}, "head.ini"))
    assert device.last_error == "device 'strict_board': head.ini['axes']: key 'axes': this board has exactly 4"
    assert not device.open("not_a_device")
    assert "returned str, not a DeviceDriver" in device.last_error


class PatternCamera(DeviceDriver, IFrameGrabberImage):
    """A camera in Python: every frame is one colour, the next one brighter."""

    def open(self, config):
        self.size = (config.get_int("width", 8, 1, 64), config.get_int("height", 6, 1, 64))
        self.frame = 0
        return True

    def close(self):
        return True

    def width(self):
        return self.size[0]

    def height(self):
        return self.size[1]

    def getImage(self):
        image = ImageRgb(*self.size)
        self.frame += 1
        image.pixels = bytes([self.frame % 256, 7, 200]) * (self.size[0] * self.size[1])
        return image


def test_a_python_camera_is_served_by_the_cpp_grabber_server_to_the_cpp_remote_grabber(name_server):
    factory = DriverFactory.instance()
    if not factory.has("pattern_camera"):
        factory.add("pattern_camera", "one colour per frame", PatternCamera)
    served = PolyDriver(Property.from_dict({"device": "frameGrabber_nws_yarp", "subdevice": "pattern_camera",
                                            "width": 5, "height": 4, "period": 0.01, "name": "/pycam",
                                            "server": name_server.address}))
    with served:
        assert served.is_valid(), served.last_error
        with PolyDriver(Property.from_dict({"device": "remote_grabber", "remote": "/pycam", "local": "/pyview",
                                            "server": name_server.address})) as remote:
            assert remote.is_valid(), remote.last_error
            frames = remote.view(IFrameGrabberImage)
            assert (frames.width(), frames.height()) == (5, 4)  # by RPC to the Python camera
            image = frames.getImage()  # streamed: encoded by the C++ server, decoded by the C++ client
            assert (image.width, image.height) == (5, 4)
            first = image.pixel(0, 0)
            assert first[1:] == (7, 200) and image.pixels == bytes(first) * 20


def test_structs_and_enums_are_the_idl_ones():
    pid = Pid(kp=1.5, ki=0.25)
    assert (pid.kp, pid.ki, pid.kd) == (1.5, 0.25, 0.0)
    assert pid == Pid(kp=1.5, ki=0.25) and pid != Pid()
    assert int(ControlMode.POSITION) == int.from_bytes(b"pos\0", "little")
    assert IEncoders.FINGERPRINT == "ac82e96ba9e4ba10" and IEncoders.INTERFACE_NAME == "IEncoders"
