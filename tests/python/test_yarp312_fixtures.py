# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""YARP 3.12.3 by its recorded bytes (tests/vectors/yarp312/, README.md there): CI builds only YARP
3.5, so these fixtures are the 3.12 test. Every recorded message decodes and re-encodes byte for
byte; our servers answer the requests 3.12.3's tools and clients sent in the shapes 3.12.3's servers
answered them; our clients send the bytes 3.12.3's clients send and read 3.12.3's replies (the
camera's [fgc] [set] <int32> included); and our C++ clients, against a server replaying 3.12.3,
never send it the fingerprint request [get] [rgif], which a Robogene server still gets."""
from __future__ import annotations

import socket
import threading
import time

import pytest

from robogene import Bottle, Network, decode_joint_data, vocab
from robogene.dev import (CameraFeature, ControlboardClient, ControlboardServer, ControlMode, DeviceDriver,
                          FeatureMode, GrabberClient, GrabberServer, IEncoders, IFrameGrabberControls, Pid, PidType,
                          PolyDriver, Property)

import yarp312
from idl_wire import INTERFACES, SERVICES, STRUCTS

pytestmark = pytest.mark.timeout(120)

FIXTURE_FILES = sorted(p.name for p in yarp312.FIXTURES.glob("*.txt"))
OK_CODE, TSTA_CODE = vocab("ok"), vocab("tsta")


def bottle(payload: bytes) -> Bottle:
    return Bottle.from_bytes(payload)


def shape(b: Bottle, top: bool = True) -> list:
    """What a client of YARP's relies on in a reply: every item's type, and the vocabs of its head
    (the first two items: [is] [axes], [fgc] [feat]); later vocabs are values (a control mode)."""
    out = []
    for i in range(len(b)):
        v = b[i]
        if v.is_list():
            out.append(("list", shape(v.as_list(), False)))
        elif v.is_vocab():
            out.append(("vocab", v.as_vocab()) if top and i < 2 or v.as_vocab() in (OK_CODE, TSTA_CODE) else "vocab")
        elif v.is_int():
            out.append("int")
        elif v.is_float():
            out.append("float")
        elif v.is_string():
            out.append("string")
        else:
            out.append(v.to_text())
    return out


def requests_and_replies(name: str):
    for conn in yarp312.load(name):
        for m in conn.messages:
            if m.command == "d":
                yield conn, m


# ---- the fixtures themselves --------------------------------------------------------------------

@pytest.mark.parametrize("name", FIXTURE_FILES)
def test_every_recorded_message_decodes_and_reencodes_byte_for_byte(name):
    seen = 0
    for conn in yarp312.load(name):
        for m in conn.messages:
            for payload in (m.payload, m.reply):
                if payload:
                    assert bottle(payload).to_bytes() == payload, (name, conn.sender, payload.hex())
                    seen += 1
    assert seen, f"{name} holds no message"


# ---- our servers, asked what YARP 3.12.3 was asked ------------------------------------------------

# Where YARP 3.12.3 and we answer differently: request text -> why. Every other request must get
# 3.12.3's reply shape, and any other difference in success fails the test.
KNOWN_DIFFERENCES = {"controlboard": {
    # Of the servers (docs/interop.md, "YARP 3.12.3 by fixtures"):
    "[set] [vmo] 1 0.25": "YARP's server refuses a single-joint velocity move by RPC (its client streams it)",
    "[get] [torq] [axes]": "YARP 3.12.3's server answers [fail]; ours the number of axes",
    # Of the devices: test_motor and YARP's fakeMotionControl are different simulations.
    "[set] [pid] [ref] [pos] 1 0.25": "test_motor's loops track ideally: no reference to set",
    "[set] [pid] [refs] [pos] (0.25 0.25 0.25 0.25)": "the same, all axes",
    "[get] [pid] [ref] [pos] 1": "test_motor: the axis is not running its position loop (torque mode)",
    "[get] [pid] [refs] [pos]": "the same, all axes",
    "[get] [pid] [err] [pos] 1": "the same",
    "[get] [pid] [errs] [pos]": "the same, all axes",
    "[get] [pid] [out] [pos] 1": "the same",
    "[get] [pid] [outs] [pos]": "the same, all axes",
    "[set] [icmd] [cmod] 1 [pos]": "test_motor refuses position mode after [set] [pid] [dis] [pos] 1 until enabled",
    "[set] [icmd] [cmds] ([pos] [pos] [pos] [pos])": "the same, all axes",
}, "grabber": {}}
FAILURES = ("[fail]", "[nak]")


def compare_with_yarp(name: str, ask) -> tuple[int, dict]:
    """(requests compared, {request: (YARP's reply, ours)} where the two differ)."""
    compared, differing = 0, {}
    for _, m in requests_and_replies(name):
        request, theirs = bottle(m.payload), bottle(m.reply)
        ours = ask(request)
        if request.to_text() == "[get] [rgif]":  # YARP: [fail] and an error in its log; we list our interfaces
            assert theirs.to_text() == "[fail]" and ours.to_text().startswith("[is] [rgif] ((")
            continue
        if (theirs.to_text() in FAILURES) != (ours.to_text() in FAILURES) or \
                (theirs.to_text() not in FAILURES and shape(ours) != shape(theirs)):
            differing[request.to_text()] = (theirs.to_text(), ours.to_text())
            continue
        assert shape(ours) == shape(theirs), f"{request.to_text()}: YARP 3.12.3 {theirs.to_text()}, ours {ours.to_text()}"
        compared += 1
    return compared, differing


def python_server(service: str):
    """A device opened from Python and the generated server dispatch over it, without ports."""
    if service == "controlboard":
        device = PolyDriver(Property.from_dict({"device": "test_motor", "axes": 4, "clock": "manual"}))
        return device, ControlboardServer(device.view(DeviceDriver))
    device = PolyDriver(Property.from_dict({"device": "fake_grabber", "width": 8, "height": 4, "clock": "manual"}))
    return device, GrabberServer(device.view(DeviceDriver))


@pytest.mark.parametrize("name,service", [("controlboard_rpc.txt", "controlboard"),
                                          ("grabber_rpc.txt", "grabber")])
def test_our_python_servers_answer_in_yarp_3_12_shapes(name, service):
    device, server = python_server(service)
    compared, differing = compare_with_yarp(name, server.respond)
    assert set(differing) == set(KNOWN_DIFFERENCES[service]), differing
    assert compared >= (50 if service == "controlboard" else 9)
    device.close()


@pytest.mark.parametrize("name,service", [("remote_controlboard.txt", "controlboard"),
                                          ("frame_grabber_nwc.txt", "grabber")])
def test_our_python_servers_answer_what_yarp_3_12_clients_send(name, service):
    """The requests YARP 3.12.3's own remote_controlboard and frameGrabber_nwc_yarp sent (their
    bytes, not yarp rpc's) get 3.12.3's reply shapes from our server too."""
    device, server = python_server(service)
    compared, differing = compare_with_yarp(name, server.respond)
    assert set(differing) <= set(KNOWN_DIFFERENCES[service]), differing
    assert compared >= (40 if service == "controlboard" else 9)
    device.close()


@pytest.mark.parametrize("name,service,args,port", [
    ("controlboard_rpc.txt", "controlboard", ["--device", "test_motor", "--axes", "4", "--clock", "manual"], "/rg/rpc:i"),
    ("grabber_rpc.txt", "grabber", ["--device", "fake_grabber", "--width", "8", "--height", "4"], "/rg/rpc")])
def test_our_cpp_servers_answer_in_yarp_3_12_shapes(name, service, args, port, name_server, procs, robogene_bin,
                                                    yarp_env):
    dev = procs.start("robogene dev", [robogene_bin, "dev", *args, "--name", "/rg"], yarp_env)
    dev.wait_for_line(r"serving on ", stream="err")
    network = Network(name_server.address)
    compared, differing = compare_with_yarp(name, lambda request: network.rpc(port, request))
    assert set(differing) == set(KNOWN_DIFFERENCES[service]), differing
    assert compared >= (50 if service == "controlboard" else 9)


def test_a_yarp_3_12_camera_set_reply_is_what_our_servers_send():
    """YARP 3.12.3's frameGrabber_nws_yarp, its camera reached through YARP's frameGrabber_nwc_yarp
    (grabber_rpc_chain.txt), answered a set that was done with [fgc] [set] 1 and one that was not
    with [fgc] [set] 0: byte for byte our servers' answers."""
    device, server = python_server("grabber")
    answers = {}
    for _, m in requests_and_replies("grabber_rpc_chain.txt"):
        request = bottle(m.payload)
        if request.to_text().startswith("[fgc] [set]"):
            answers[request.to_text()] = (m.reply, server.respond(request).to_bytes())
    assert answers
    for text, (theirs, ours) in answers.items():
        assert ours == theirs, f"{text}: YARP 3.12.3 {bottle(theirs).to_text()}, ours {bottle(ours).to_text()}"
    assert {bottle(t).to_text() for t, _ in answers.values()} >= {"[fgc] [set] 1", "[fgc] [set] 0"}
    device.close()


# ---- our clients, given YARP 3.12.3's replies -----------------------------------------------------

EXAMPLES = {"joint": 1, "float64": 0.25, "int32": 3, "bool": True, "CameraFeature": CameraFeature(7),
            "FeatureMode": FeatureMode(2), "PidType": PidType.POSITION, "ControlMode": ControlMode.POSITION}


def example(t: str, axes: int = 4):
    """The arguments requests_from_idl.py gave `yarp rpc`, as Python values."""
    if t.endswith("[]"):
        return [example(t[:-2], axes) for _ in range(axes)]
    if t in STRUCTS:
        return Pid(*[k + 1.5 for k in range(len(STRUCTS[t]))])
    return EXAMPLES[t]


class Replay:
    """A client transport answering with YARP 3.12.3's recorded reply to the same request bytes."""

    def __init__(self, *names: str):
        self.replies = yarp312.exchanges(*names)
        self.missing: list[str] = []
        self.sent: list[str] = []
        self.last = ""

    def __call__(self, request: Bottle) -> Bottle:
        self.sent.append(request.to_text())
        reply = self.replies.get(request.to_bytes())
        if reply is None:
            self.missing.append(request.to_text())
            reply = Bottle.from_text("[fail]").to_bytes()
        self.last = bottle(reply).to_text()
        return bottle(reply)


# Where our client does not take YARP 3.12.3's reply as the generic rule says: (fixture, method) -> why.
CLIENT_REFUSES = {
    # fakeFrameGrabber refuses every control, and 3.12.3's server still sends the value it never set:
    ("grabber_rpc.txt", "hasFeature"): "an uninitialised bool (32), which our client refuses as not a bool",
    ("grabber_rpc.txt", "getActive"): "the same",
    ("grabber_rpc.txt", "getMode"): "an uninitialised int that is no FeatureMode",
}


def expected_outcome(service: str, reply: str, is_query: bool) -> bool:
    """Whether a client must report success for YARP 3.12.3's `reply`."""
    if reply in ("[fail]", "[nak]"):
        return False
    if is_query:
        return True
    if service == "grabber":  # [fgc] [set] <int32>: whether the camera did it
        return reply.split()[-1] != "0"
    return reply == "[ok]"


@pytest.mark.parametrize("service,client_class,names", [
    ("controlboard", ControlboardClient, ("controlboard_rpc.txt",)),
    ("grabber", GrabberClient, ("grabber_rpc.txt",)),
    ("grabber", GrabberClient, ("grabber_rpc_chain.txt",))])
def test_our_python_clients_send_yarps_bytes_and_read_its_replies(service, client_class, names):
    replay = Replay(*names)
    client = client_class(replay)
    assert client.check_server(False) == []  # YARP's: [prot] 1 9 0 [ok] for the control board, nothing asked of a camera
    assert "[get] [rgif]" not in replay.sent
    called = 0
    for iface in SERVICES[service][1]:
        for method, (wire, args, results) in INTERFACES[iface][1].items():
            if wire is None:
                continue
            got = getattr(client, method)(*[example(a) for a in args])
            assert not replay.missing, f"{method}: YARP 3.12.3 was never sent {replay.missing}"
            success = got is not None if results else got
            expected = expected_outcome(service, replay.last, bool(results)) and (names[0], method) not in CLIENT_REFUSES
            assert success == expected, \
                f"{method}: YARP 3.12.3 answered {replay.last}, our client returned {got!r}"
            called += 1
    assert called >= 9


# ---- our C++ clients on the network, against a server that replays YARP 3.12.3 ----------------------

def replay_server(network: Network, prefix: str, ports, names, stream=None) -> yarp312.ReplayServer:
    server = yarp312.ReplayServer(yarp312.exchanges(*names), stream)
    server.resolve = lambda name: (lambda c: (c.host, c.port) if c else None)(network.query(name))
    for port in ports:
        network.register(prefix + port, "tcp", "127.0.0.1", server.port)
    return server


def recorded_stream(name: str, sender_suffix: str) -> list[bytes]:
    return [m.payload for c in yarp312.load(name) if c.sender.endswith(sender_suffix) for m in c.messages
            if m.command == "D"]


def test_our_remote_controlboard_never_asks_a_yarp_3_12_server_for_fingerprints(name_server, procs, robogene_bin,
                                                                              yarp_env):
    network = Network(name_server.address)
    joints = recorded_stream("streams.txt", "/stateExt:o")
    assert joints, "streams.txt holds no stateExt:o message"
    server = replay_server(network, "/y312", ["/rpc:i", "/command:i", "/stateExt:o"],
                           ("controlboard_rpc.txt", "remote_controlboard.txt"), joints)
    try:
        dev = procs.start("robogene dev", [robogene_bin, "dev", "--device", "controlBoard_nws_yarp", "--subdevice",
                                           "remote_controlboard", "--remote", "/y312", "--local", "/ours",
                                           "--carrier", "tcp", "--name", "/ourproxy"], yarp_env)
        dev.wait_for_line(r"serving on ", stream="err", timeout=20)
        ask = lambda text: network.rpc("/ourproxy/rpc:i", Bottle.from_text(text))
        assert ask("[get] [axes]").to_text().startswith("[is] [axes] 4 ")
        # Encoders come from YARP 3.12.3's recorded stateExt:o, replayed by the server.
        expected = list(decode_joint_data(bottle(joints[0])).position)
        deadline = time.monotonic() + 10
        while server.streamed < 10:
            assert time.monotonic() < deadline, "the replayed stateExt:o does not flow"
            time.sleep(0.05)
        asked_before = len(server.received)
        assert [v.as_float() for v in ask("[get] [encs]")[2].as_list()] == expected
        encs = Bottle.from_text("[get] [encs]").to_bytes()
        assert encs not in [p for _, _, p in server.received[asked_before:]], "read by RPC, not from the stream"
        assert ask("[set] [pos] 1 0.25").to_text() == "[ok]"
        sent = server.sent_bytes()
        assert b"rgif" not in sent, "the fingerprint request reached a YARP 3.12.3 server"
        assert "[prop] [get] robogene_service" in server.admin  # asked of the port, not of the device
        assert [r for r in server.unknown if b"rgif" in r] == []
        assert not server.unknown, [bottle(r).to_text() for r in server.unknown]
    finally:
        server.close()


def test_our_remote_grabber_reads_yarp_3_12_set_replies(name_server, procs, robogene_bin, yarp_env):
    network = Network(name_server.address)
    server = replay_server(network, "/y312cam", ["", "/rpc"], ("grabber_rpc_chain.txt",))
    try:
        dev = procs.start("robogene dev", [robogene_bin, "dev", "--device", "grabberDual", "--subdevice",
                                           "remote_grabber", "--remote", "/y312cam", "--local", "/ourcam",
                                           "--name", "/ourcamproxy"], yarp_env)
        dev.wait_for_line(r"serving on ", stream="err", timeout=20)
        ask = lambda text: network.rpc("/ourcamproxy/rpc", Bottle.from_text(text)).to_text()
        done = {bottle(m.payload).to_text(): bottle(m.reply).to_text()
                for _, m in requests_and_replies("grabber_rpc_chain.txt")
                if bottle(m.payload).to_text().startswith("[fgc] [set]")}
        for request, yarps in done.items():
            # Our client reads YARP 3.12.3's [fgc] [set] 1 as done and 0 as refused; our server says so.
            assert ask(request) == yarps, request
        assert b"rgif" not in server.sent_bytes()
        assert not server.unknown, [bottle(r).to_text() for r in server.unknown]
    finally:
        server.close()


class RecordingRelay:
    """A TCP relay that keeps what clients send: put before our own server, it shows the questions
    our clients ask a Robogene server."""

    def __init__(self, target: tuple[str, int]):
        self.target = target
        self.sent = b""
        self._lock = threading.Lock()
        self._sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self._sock.bind(("127.0.0.1", 0))
        self._sock.listen(8)
        self.port = self._sock.getsockname()[1]
        threading.Thread(target=self._accept, daemon=True).start()

    def _accept(self) -> None:
        while True:
            try:
                client, _ = self._sock.accept()
            except OSError:
                return
            upstream = socket.create_connection(self.target)
            for src, dst, keep in ((client, upstream, True), (upstream, client, False)):
                threading.Thread(target=self._pump, args=(src, dst, keep), daemon=True).start()

    def _pump(self, src, dst, keep) -> None:
        try:
            while True:
                data = src.recv(65536)
                if not data:
                    break
                if keep:
                    with self._lock:
                        self.sent += data
                dst.sendall(data)
        except OSError:
            pass
        finally:
            for s in (src, dst):
                try:
                    s.shutdown(socket.SHUT_RDWR)
                except OSError:
                    pass

    def close(self) -> None:
        self._sock.close()


def test_our_remote_controlboard_still_asks_our_server_for_fingerprints(name_server, procs, robogene_bin, yarp_env):
    network = Network(name_server.address)
    dev = procs.start("robogene dev", [robogene_bin, "dev", "--device", "test_motor", "--axes", "2", "--name",
                                       "/motors"], yarp_env)
    dev.wait_for_line(r"serving on ", stream="err")
    relays = []
    try:
        for port in ("/rpc:i", "/command:i", "/stateExt:o"):
            where = network.query("/motors" + port)
            relays.append(RecordingRelay((where.host, where.port)))
            network.register("/relayed" + port, "tcp", "127.0.0.1", relays[-1].port)
        client = procs.start("robogene dev", [robogene_bin, "dev", "--device", "controlBoard_nws_yarp", "--subdevice",
                                              "remote_controlboard", "--remote", "/relayed", "--local", "/ours",
                                              "--carrier", "tcp", "--name", "/ourproxy"], yarp_env)
        client.wait_for_line(r"serving on ", stream="err", timeout=20)
        assert network.rpc("/ourproxy/rpc:i", Bottle.from_text("[get] [axes]")).to_text().startswith("[is] [axes] 2 ")
        rpc_bytes = relays[0].sent
        assert b"robogene_service" in rpc_bytes  # the admin question, on the rpc port's own address
        assert Bottle.from_text("[get] [rgif]").to_bytes() in rpc_bytes  # and then the fingerprints
    finally:
        for r in relays:
            r.close()


def test_our_python_clients_never_ask_a_yarp_3_12_server_for_fingerprints(name_server):
    """remote_controlboard and remote_grabber, opened from Python, against servers replaying YARP 3.12.3."""
    network = Network(name_server.address)
    joints = recorded_stream("streams.txt", "/stateExt:o")
    motors = replay_server(network, "/y312py", ["/rpc:i", "/command:i", "/stateExt:o"],
                           ("controlboard_rpc.txt", "remote_controlboard.txt"), joints)
    camera = replay_server(network, "/y312pycam", ["", "/rpc"], ("grabber_rpc_chain.txt",))
    try:
        board = PolyDriver(Property.from_dict({"device": "remote_controlboard", "remote": "/y312py",
                                               "local": "/pyours", "carrier": "tcp", "server": name_server.address}))
        assert board.is_valid(), board.last_error
        assert board.view(IEncoders).getAxes() == 4
        board.close()
        cam = PolyDriver(Property.from_dict({"device": "remote_grabber", "remote": "/y312pycam", "local": "/pyourcam",
                                             "server": name_server.address}))
        assert cam.is_valid(), cam.last_error
        assert cam.view(IFrameGrabberControls).setFeature(CameraFeature.SHUTTER, 0.25) is True  # [fgc] [set] 1
        cam.close()
        for server in (motors, camera):
            assert b"rgif" not in server.sent_bytes()
            assert "[prop] [get] robogene_service" in server.admin
    finally:
        motors.close()
        camera.close()
