# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""RPC from Python: the generated server dispatch, bound from C++ (robogene.dev.ControlboardServer),
replays a real YARP 3 `yarp rpc` session byte for byte (the same capture as the C++ test,
rpc_motors.flows.txt), and the generated client (ControlboardClient, over a Python transport)
drives a device through bytes and the server. Needs the compiled core (`make python`)."""
import math
import struct
import time

import pytest

from robogene import Bottle, Error
from robogene.dev import (CameraFeature, ControlboardClient, ControlboardServer, ControlMode, DeviceDriver,
                          FeatureMode, GrabberClient, GrabberServer, IEncoders, IPositionControl, ISimulationClock,
                          IVelocityControl, Pid, PidType, PolyDriver, Property)

# (typed at yarp rpc, request bytes, reply bytes) from the capture; see the C++ twin
# drivers/fake/test/framework/controlboard_server_test.cpp for the one deliberate difference ([vel] modes).
SESSION = [
    ("get axes", "0401000002000000030000006765740400000061786573",
     "000100000700000009000000697300000400000004000000617865730100000004000000090000007473746101000000000000000a0000004a7cad51a2c0da41090000006f6b0000"),
    ("[get] [axes]", "09010000020000006765740061786573",
     "0001000007000000090000006973000009000000617865730100000004000000090000007473746101000000010000000a000000d17fad51a2c0da41090000006f6b0000"),
    ("get prot", "0401000002000000030000006765740400000070726f74",
     "00010000050000000900000070726f74010000000100000001000000090000000100000000000000090000006f6b0000"),
    ("set pos 0 10", "000100000400000004000000030000007365740400000003000000706f730100000000000000010000000a000000",
     "09010000010000006f6b0000"),
    ("set vel 0 20", "00010000040000000400000003000000736574040000000300000076656c01000000000000000100000014000000",
     "09010000010000006f6b0000"),
    ("get pos 0", "000100000300000004000000030000006765740400000003000000706f730100000000000000",
     "000100000700000009000000697300000400000003000000706f730a0000000000000000002440090000007473746101000000020000000a000000fb87ad51a2c0da41090000006f6b0000"),
    ("get enc 0", "000100000300000004000000030000006765740400000003000000656e630100000000000000",
     "000100000700000009000000697300000400000003000000656e630a0000000000000000000000090000007473746101000000030000000a000000788aad51a2c0da41090000006f6b0000"),
    ("get encs", "04010000020000000300000067657404000000656e6373",
     "000100000700000009000000697300000400000004000000656e63730a010000040000000000000000000000000000000000000000000000000000000000000000000000090000007473746101000000040000000a000000cc8cad51a2c0da41090000006f6b0000"),
    ("set poss (1 2 3 4)", "000100000300000004000000030000007365740400000004000000706f7373010100000400000001000000020000000300000004000000",
     "09010000010000006f6b0000"),
    ("get done 0", "000100000300000004000000030000006765740400000004000000646f6e650100000000000000",
     "09010000010000006661696c"),
    ("set vmos (0.5 0 0 0)", "000100000300000004000000030000007365740400000004000000766d6f7300010000040000000a000000000000000000e03f010000000000000001000000000000000100000000000000",
     "09010000010000006f6b0000"),
    ("get vmo 0", "000100000300000004000000030000006765740400000003000000766d6f0100000000000000",
     "000100000700000009000000697300000400000003000000766d6f0a000000000000000000e03f090000007473746101000000060000000a000000db99ad51a2c0da41090000006f6b0000"),
    ("get icmd cmds", "0401000003000000030000006765740400000069636d6404000000636d6473",
     "0001000007000000090000006973000009000000636d6473090100000400000076656c0076656c0076656c0076656c00090000007473746101000000070000000a000000c49cad51a2c0da41090000006f6b0000"),
    ("get foo", "04010000020000000300000067657403000000666f6f", "09010000010000006661696c"),
]


def board(axes=4):
    device = PolyDriver(Property.from_dict({"device": "test_motor", "axes": axes, "clock": "manual"}))
    assert device.is_valid(), device.last_error
    return device, ControlboardServer(device.view(DeviceDriver))


def test_server_replays_the_captured_yarp_session_byte_for_byte():
    _, server = board()
    for text, request, expected in SESSION:
        before = time.time()
        got = server.respond(Bottle.from_bytes(bytes.fromhex(request))).to_bytes()
        after = time.time()
        want = bytes.fromhex(expected)
        assert len(got) == len(want), text
        if len(want) > 20 and want[-20:-16] == b"\x0a\0\0\0":  # [tsta] n <time> [ok]
            assert got[:-16] + got[-8:] == want[:-16] + want[-8:], text
            assert before <= struct.unpack("<d", got[-16:-8])[0] <= after, text
        else:
            assert got == want, text


def test_server_answers_help_with_a_usage_line_per_request():
    _, server = board()
    for request in ("help", "[help]"):
        reply = server.respond(Bottle.from_text(request))
        assert reply[0].to_text() == "[many]"
        lines = [reply[i].as_string() for i in range(1, len(reply))]
        assert lines[0] == "[get] [axes]  # The number of axes the board controls."
        assert "[set] [pos] $j $ref  # Start moving one axis to an absolute position. (ref: deg)" in lines
    assert server.respond(Bottle.from_text("helper")).to_text() == "[nak]"


def test_server_refuses_malformed_requests():
    _, server = board()
    ask = lambda text: server.respond(Bottle.from_text(text)).to_text()  # noqa: E731
    assert ask("[bogus]") == "[nak]"
    assert ask("[set] [pos] 1") == "[fail]"
    assert ask("[set] [pos] one 2.0") == "[fail]"
    assert ask("[set] [pos] 9 2.0") == "[fail]"
    assert ask("[set] [poss] (1.0 2.0)") == "[fail]"
    assert ask("[set] [icmd] [cmod] 0 [bogu]") == "[fail]"
    assert ask("[get] [torq] [trq] 9") == "[fail]"  # no such axis
    assert ask("[set] [torq] [ref] 0 99.0") == "[fail]"  # beyond max_torque
    assert ask("[get] [pid] [pid] [xyz] 0") == "[fail]"  # not a PID type
    assert ask("[set] [pid] [pid] [pos] 0 (1.0 2.0)") == "[fail]"  # 2 of a Pid's 10 fields
    assert ask("[get] [icmd] [cmod] 0").startswith("[is] 0 [pos] [tsta] ")


def client_for(server, tamper=None):
    def transport(request):
        on_server = Bottle.from_bytes(request.to_bytes())
        reply = server.respond(on_server)
        if tamper:
            reply = tamper(on_server, reply)
        return Bottle.from_bytes(reply.to_bytes())
    return ControlboardClient(transport)


def test_paper_section_3_3_through_client_bytes_and_server():
    device, server = board(3)
    client = client_for(server)
    assert [name for name, _ in client.check_server(True)] == [
        "IEncoders", "IPositionControl", "IVelocityControl", "ITorqueControl", "IPidControl", "IControlMode"]
    ipos, ivel = client, client
    assert isinstance(ipos, IPositionControl) and isinstance(ivel, IVelocityControl)
    assert ipos.setRefAcceleration(0, 100) and ipos.setRefSpeed(0, 5) and ipos.positionMove(0, 40)
    assert ivel.setRefAcceleration(1, 100) and ivel.velocityMove(1, 5)
    assert device.view(ISimulationClock).advance(4.0)
    encs = client.getEncoders()
    assert encs[0] == pytest.approx(0.125 + 5 * 3.95, abs=0.01)
    assert encs[1] == pytest.approx(0.125 + 5 * 3.95, abs=0.01)
    assert [client.checkMotionDone(j) for j in range(3)] == [False, False, True]
    assert client.checkMotionDoneAll() is False  # one value for all axes, as YARP answers [get] [dons]
    assert client.getControlModes() == [ControlMode.POSITION, ControlMode.VELOCITY, ControlMode.POSITION]
    assert client.setControlMode(2, ControlMode.PWM) is False
    assert client.getTorque(7) is None  # no such axis
    assert client.getAxes() == 3


def test_torque_and_pid_replies_have_yarps_shapes():
    """As handleTorqueMsg and handlePidMsg answer: torque queries are stamped, PID queries are not
    (and take no stamp number); a Pid is the list of its 10 fields."""
    _, server = board()
    ask = lambda text: server.respond(Bottle.from_text(text)).to_text()  # noqa: E731
    assert ask("[set] [torq] [refs] (0.25 0.5 0.75 1.0)") == "[ok]"
    assert ask("[get] [torq] [trq] 1").startswith("[is] [torq] 0.5 [tsta] ")
    stamp = server.respond(Bottle.from_text("[get] [axes]"))[4].as_int()
    assert ask("[set] [pid] [pid] [pos] 2 (1.0 2.0 3.0 4.0 5.0 6.0 7.0 8.0 9.0 10.0)") == "[ok]"
    reply = server.respond(Bottle.from_text("[get] [pid] [pid] [pos] 2"))
    assert reply.to_text() == "[is] [pid] (1.0 2.0 3.0 4.0 5.0 6.0 7.0 8.0 9.0 10.0) [ok]"
    assert reply.to_bytes().hex() == ("0001000004000000" "0900000069730000" "0900000070696400" "0a0100000a000000"
                                      + struct.pack("<10d", *range(1, 11)).hex() + "090000006f6b0000")
    assert ask("[get] [pid] [outs] [trq]") == "[is] [pid] (0.25 0.5 0.75 1.0) [ok]"
    assert ask("[get] [pid] [ref] [pos] 1") == "[fail]"  # axis 1 runs its torque loop
    assert ask("[set] [pid] [ref] [trq] 1 0.5") == "[fail]"  # direct references: not simulated
    assert server.respond(Bottle.from_text("[get] [axes]"))[4].as_int() == stamp + 1


def test_torque_control_and_pids_through_client_bytes_and_server():
    """The C++ twin is ControlboardClient.TorqueControlAndPidsSucceedThroughTheWire."""
    device, server = board(3)
    client = client_for(server)
    assert client.setRefTorque(0, 0.5)
    assert client.getControlMode(0) == ControlMode.TORQUE
    assert device.view(ISimulationClock).advance(1.0)  # 50 time constants of J/b = 0.02 s
    assert client.getTorque(0) == 0.5 and client.getRefTorque(0) == 0.5
    terminal = 0.5 / 0.5 * 180.0 / math.pi  # t / b, deg/s
    assert client.getEncoderSpeed(0) == pytest.approx(terminal, abs=1e-9)
    assert client.getEncoder(0) == pytest.approx(terminal * (1 - 0.02), abs=1e-9)
    assert client.getTorqueRange(2) == (-5.0, 5.0)
    assert client.setRefTorque(1, 5.5) is False
    assert client.setRefTorques([1.0, 2.0, -6.0]) is False  # one bad entry: nothing changes
    assert client.getRefTorques() == [0.5, 0.0, 0.0]

    assert client.setRefAcceleration(1, 100.0) and client.velocityMove(1, 10.0)
    assert device.view(ISimulationClock).advance(1.0)
    torque = client.getTorque(1)
    assert torque == pytest.approx(0.5 * 10.0 * math.pi / 180.0, abs=1e-12)  # b w
    assert client.getPidOutput(PidType.VELOCITY, 1) == torque
    assert (client.getPidReference(PidType.VELOCITY, 1), client.getPidError(PidType.VELOCITY, 1)) == (10.0, 0.0)
    assert client.getPidReference(PidType.TORQUE, 1) is None
    assert client.getPidErrors(PidType.POSITION) is None  # not every axis runs it

    gains = Pid(6000, 500, 5, 1333, 1333, 0, 8, 0.5, -0.5, 1)
    assert client.setPid(PidType.POSITION, 2, gains)
    assert client.getPid(PidType.POSITION, 2) == gains
    assert client.getPids(PidType.POSITION) == [Pid(), Pid(), gains]
    assert client.getPids(PidType.TORQUE) == [Pid()] * 3
    assert client.setPid(PidType.VELOCITY, 0, Pid(ki=float("nan"))) is False
    assert client.setPids(PidType.VELOCITY, [gains, gains]) is False
    assert client.setPids(PidType.CURRENT, [gains, Pid(), gains])
    assert client.getPids(PidType.CURRENT) == [gains, Pid(), gains]
    assert client.setPidErrorLimits(PidType.POSITION, [1.0, 2.0, 3.0])
    assert client.setPidErrorLimit(PidType.POSITION, 0, -1.0) is False
    assert client.getPidErrorLimits(PidType.POSITION) == [1.0, 2.0, 3.0]

    assert client.positionMove(2, 20.0)
    assert client.getPidError(PidType.POSITION, 2) == 20.0
    assert device.view(ISimulationClock).advance(10.0)
    assert (client.getPidReference(PidType.POSITION, 2), client.getPidError(PidType.POSITION, 2)) == (20.0, 0.0)
    assert client.setPidReference(PidType.POSITION, 2, 5.0) is False


def test_client_refuses_a_server_built_from_other_idl():
    _, server = board()

    def tamper(request, reply):
        if request[1].as_vocab_text() == "rgif":
            text = reply.to_text()
            fp = IPositionControl.FINGERPRINT
            return Bottle.from_text(text.replace(fp, "0123456789abcdef"))
        return reply
    with pytest.raises(Error, match="interface IPositionControl has fingerprint 0123456789abcdef, "
                                    f"this client was generated for {IPositionControl.FINGERPRINT}"):
        client_for(server, tamper).check_server(True)


def test_client_checks_a_yarp_server_by_protocol_version_and_never_asks_it_for_fingerprints():
    _, server = board()

    asked = []

    def yarp_like(minor):
        def tamper(request, reply):
            word = request[1].as_vocab_text()
            asked.append(word)
            if word == "rgif":  # YARP 3.12 logs it as an error: never to be asked
                return Bottle.from_text("[fail]")
            if word == "prot":
                return Bottle.from_text(f"[prot] 1 {minor} 0 [ok]")
            return reply
        return tamper
    assert client_for(server, yarp_like(9)).check_server(False) == []
    with pytest.raises(Error, match=r"^controlboard server speaks protocol 1\.8, this client speaks 1\.9$"):
        client_for(server, yarp_like(8)).check_server(False)
    assert asked == ["prot", "prot"]


def test_a_server_that_says_it_is_robogenes_must_list_its_interfaces():
    _, server = board()
    tamper = lambda request, reply: Bottle.from_text("[fail]") if request[1].as_vocab_text() == "rgif" else reply
    with pytest.raises(Error, match=r"^controlboard server says it is Robogene's but does not list its "
                                    r"interfaces: \[fail\]$"):
        client_for(server, tamper).check_server(True)


def test_command_port_carries_streamed_moves():
    _, server = board()
    vmo = Bottle.from_bytes(bytes.fromhex(
        "0001000002000000" "000100000200000009000000766d6f000100000002000000"
        "0a01000001000000" + "000000000000" + "1e40"))
    assert vmo.to_text() == "([vmo] 2) (7.5)"
    assert server.command(vmo)
    assert server.respond(Bottle.from_text("[get] [vmo] 2")).to_text().startswith("[is] [vmo] 7.5 [tsta]")
    assert server.command(Bottle.from_text("([poss]) (10.0 20.0 30.0 40.0)"))
    assert server.respond(Bottle.from_text("[get] [poss]")).to_text().startswith(
        "[is] [poss] (10.0 20.0 30.0 40.0)")
    for bad in ("([vmo] 9) (1.0)", "([bogus] 1) (1.0)", "([vmo] 1)", "([encs]) ()", "[vmo] 1 1.0"):
        assert server.command(Bottle.from_text(bad)) is False, bad
    # YARP 3.5's remote_controlboard streams torque references as [dtq] j and [dtqs] (IDL aliases).
    assert server.command(Bottle.from_text("([dtq] 1) (0.5)"))
    assert server.command(Bottle.from_text("([dtqs]) (0.25 0.5 0.75 1.0)"))
    assert server.respond(Bottle.from_text("[get] [torq] [refs]")).to_text().startswith(
        "[is] [torq] (0.25 0.5 0.75 1.0) [tsta]")
    for bad in ("([dtq] 1) (9.0)", "([dtq]) (0.5)", "([dtqs]) (0.5 0.5)"):
        assert server.command(Bottle.from_text(bad)) is False, bad


def test_stream_messages_match_yarp():
    device, server = board()
    assert device.view(IEncoders).setEncoders([1.0, 2.0, 3.0, 4.0])
    assert server.publish_state().to_bytes().hex() == (
        "0a01000004000000000000000000f03f000000000000004000000000000008400000000000001040")
    cam = PolyDriver(Property.from_dict({"device": "fake_grabber", "width": 640, "height": 480, "clock": "manual"}))
    message = GrabberServer(cam.view(DeviceDriver)).publish_image().to_bytes()
    assert len(message) == 60 + 921600
    # The 60-byte header of a captured YARP 3 frame (sniff_image.txt).
    assert message[:60].hex() == ("0001000004000000090000006d61740009000000726762000101000005000000"
                                  "0300000000100e000800010080020000e00100000c00000000100e00")


def test_grabber_client_reads_every_form_of_a_set_reply():
    """YARP 3.12.3's [fgc] [set] <int32> says whether the set was done; Robogene's servers before it
    answered success with an empty bottle; YARP 3.5's answer [nak] to every set, and 3.12.3's to one
    they cannot parse (docs/interop.md)."""
    sent, replies = [], []

    def transport(request):
        sent.append(request.to_text())
        return Bottle.from_text(replies.pop(0))
    client = GrabberClient(transport)
    forms = {"[fgc] [set] 1": True, "[fgc] [set] 0": False, "": True, "[nak]": False, "[fgc] [set]": False,
             "[fgc] [set] [ok]": False, "[fgc] [get] 1": False, "[fgc] [set] 1 [ok]": False}
    for text, done in forms.items():
        replies.append(text)
        assert client.setFeature(CameraFeature.SHUTTER, 0.25) is done, text
    replies.extend(["[fgc] [set] 1", "[fgc] [set] 0"])
    assert client.setMode(CameraFeature.SHUTTER, FeatureMode.AUTOMATIC) is True
    assert client.setActive(CameraFeature.SHUTTER, True) is False
    assert sent[0] == "[fgc] [set] [feat] 7 0.25" and len(sent) == len(forms) + 2


def test_grabber_server_answers_a_set_as_yarp_3_12_3():
    device = PolyDriver(Property.from_dict({"device": "fake_grabber", "width": 8, "height": 4, "clock": "manual"}))
    server = GrabberServer(device.view(DeviceDriver))
    ask = lambda text: server.respond(Bottle.from_text(text)).to_text()
    assert ask("[fgc] [set] [feat] 7 0.25") == "[fgc] [set] 1"
    assert ask("fgc set feat 7 0.5") == "[fgc] [set] 1"      # in vocabs, as YARP answers
    assert ask("[fgc] [set] [feat] 10 0.5") == "[fgc] [set] 0"  # focus: refused
    assert ask("[fgc] [set] [feat] 7") == "[fgc] [set] 0"       # no value: refused
    assert ask("[fgc] [get] [feat] 7") == "[fgc] [feat] [is] 0.5"
    assert ask("[fgc] [bogus] [feat] 7") == "[nak]"
    # A client asks a server it does not know to be Robogene's nothing at all (no protocol request).
    sent = []
    client = GrabberClient(lambda request: sent.append(request.to_text()) or server.respond(request))
    assert client.check_server(False) == [] and sent == []
    assert [name for name, _ in client.check_server(True)] == ["IFrameGrabberImage", "IFrameGrabberControls"]
    assert sent == ["[get] [rgif]"]


def test_a_failing_transport_fails_the_call_and_is_reported(monkeypatch):
    """A transport that raises, returns no Bottle, or says None (the exchange failed): the client's
    call answers as for a failed request (None, False), the exception goes to sys.unraisablehook
    naming the transport, and nothing is sent twice."""
    import sys
    reported = []
    monkeypatch.setattr(sys, "unraisablehook", lambda info: reported.append(info))
    calls = []

    def raising(request):
        calls.append(request.to_text())
        raise OSError("link down")
    client = ControlboardClient(raising)
    assert client.getAxes() is None and client.positionMove(0, 1.0) is False
    assert calls == ["[get] [axes]", "[set] [pos] 0 1.0"]
    assert [type(r.exc_value) for r in reported] == [OSError, OSError]
    assert reported[0].object == "robogene client transport"

    reported.clear()
    assert ControlboardClient(lambda request: "[ok]").positionMove(0, 1.0) is False
    assert [type(r.exc_value) for r in reported] == [TypeError]
    assert "must return a Bottle or None, got str" in str(reported[0].exc_value)

    reported.clear()
    assert ControlboardClient(lambda request: None).getAxes() is None and reported == []
    with pytest.raises(TypeError, match="transport"):
        ControlboardClient("/motors/rpc:i")


class TwoAxes(DeviceDriver, IEncoders):
    """A device in Python with only IEncoders' axes."""

    def open(self, config):
        return True

    def close(self):
        return True

    def getAxes(self):
        return 2


def test_a_server_keeps_its_device_alive_and_answers_for_a_python_one():
    import gc
    server = ControlboardServer(PolyDriver(Property.from_dict({"device": "test_motor", "axes": 3})).view(DeviceDriver))
    gc.collect()  # the PolyDriver lives on in the view the server holds
    assert server.respond(Bottle.from_text("[get] [axes]")).to_text().startswith("[is] [axes] 3 [tsta] ")
    python = ControlboardServer(TwoAxes())
    gc.collect()
    assert python.interfaces() == [("IEncoders", IEncoders.FINGERPRINT)]
    assert python.respond(Bottle.from_text("[get] [axes]")).to_text().startswith("[is] [axes] 2 [tsta] ")
    assert python.respond(Bottle.from_text("[set] [pos] 0 1.0")).to_text() == "[fail]"  # no IPositionControl
