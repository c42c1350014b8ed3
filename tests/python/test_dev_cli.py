# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""`robogene dev` (the paper's yarpdev), driven from outside: the paper's section 4.4 telnet
session verbatim against `robogene dev --device test_motor --axes 2 --single_port --name /motors`,
the YARP port layout of a wrapped control board, --from ini files, and clean shutdown."""
from __future__ import annotations

import os
import re
import signal
import socket
import subprocess
import time

import pytest

pytestmark = pytest.mark.timeout(90)

# A query reply in text mode, as yarp rpc prints YARP's own (yarp-captures/yarp_rpc_motors.txt):
# [is] [axes] 4 [tsta] 1 1795328326.71092629433 [ok]
AXES_REPLY = re.compile(rb"^\[is\] \[axes\] 2 \[tsta\] \d+ \d+\.\d+ \[ok\]\r\n$")


def query(server, name: str):
    """(host, port) of `name`, or None when the name server does not know it."""
    with socket.create_connection((server.host, server.port), timeout=5) as s:
        s.sendall(f"NAME_SERVER query {name}\n".encode())
        s.shutdown(socket.SHUT_WR)
        reply = b""
        while chunk := s.recv(4096):
            reply += chunk
    m = re.match(rb"registration name \S+ ip (\S+) port (\d+) type", reply)
    return (m.group(1).decode(), int(m.group(2))) if m else None


def read_line(s: socket.socket, buffer: bytearray) -> bytes:
    while b"\r\n" not in buffer:
        chunk = s.recv(65536)
        assert chunk, f"connection closed; got {bytes(buffer)!r}"
        buffer += chunk
    end = buffer.index(b"\r\n") + 2
    line = bytes(buffer[:end])
    del buffer[:end]
    return line


def start_dev(procs, robogene_bin, yarp_env, *args: str):
    dev = procs.start("robogene dev", [robogene_bin, "dev", *args], yarp_env)
    dev.wait_for_line(r"serving on ", stream="err")
    return dev


def test_paper_section_4_4_telnet_session(name_server, procs, robogene_bin, yarp_env):
    start_dev(procs, robogene_bin, yarp_env, "--device", "test_motor", "--axes", "2", "--single_port",
              "--name", "/motors")
    at = query(name_server, "/motors")
    assert at, "/motors is not registered"
    with socket.create_connection(at, timeout=5) as s:
        buf = bytearray()
        s.sendall(b"CONNECT foo\r\n")
        assert read_line(s, buf) == b"Welcome foo\r\n"
        # The paper's session, line by line: the port's help, its description, the device's help.
        s.sendall(b"help\r\n")
        port_help = [read_line(s, buf)]
        while not port_help[-1].startswith(b"?"):
            port_help.append(read_line(s, buf))
        assert any(line.startswith(b"d ") for line in port_help), port_help
        s.sendall(b"*\r\n")
        assert read_line(s, buf) == f"This is /motors at tcp://{at[0]}:{at[1]}/\r\n".encode()
        assert read_line(s, buf) == b"There are no outgoing connections\r\n"
        assert read_line(s, buf) == b"There is an input connection from foo to /motors using text\r\n"
        s.sendall(b"d\r\nhelp\r\n")
        device_help = read_line(s, buf).decode()
        assert device_help.startswith("[many] "), device_help
        assert '"[get] [axes]  # The number of axes the board controls."' in device_help
        assert '"[set] [pos] $j $ref  # Start moving one axis to an absolute position. (ref: deg)"' in device_help
        s.sendall(b"d\r\n[get] [axes]\r\n")
        assert AXES_REPLY.match(read_line(s, buf))
        s.sendall(b"d\r\n[set] [pos] 0 100.0\r\n")
        assert read_line(s, buf) == b"[ok]\r\n"
        s.sendall(b"q\r\n")

    # A second session reverses its connection and receives the motor state: "do" then the
    # encoders, until axis 0 has arrived at 100 (10 s at test_motor's 10 deg/s).
    with socket.create_connection(at, timeout=5) as s:
        buf = bytearray()
        s.sendall(b"CONNECT foo\r\n")
        assert read_line(s, buf) == b"Welcome foo\r\n"
        s.sendall(b"r\r\n")
        deadline = time.monotonic() + 20
        positions = []
        while time.monotonic() < deadline:
            assert read_line(s, buf) == b"do\r\n"
            state = read_line(s, buf).decode()
            m = re.fullmatch(r"(\S+) (\S+)\r\n", state)
            assert m, state
            positions.append(float(m.group(1)))
            assert m.group(2) == "0.0"
            if state == "100.0 0.0\r\n":
                break
        else:
            pytest.fail(f"axis 0 never reached 100.0; last positions {positions[-5:]}")
        assert positions == sorted(positions), "the streamed encoder went backwards"
        assert len(positions) > 10


def test_a_wrapped_control_board_has_yarps_ports(name_server, procs, robogene_bin, yarp_env, cli):
    dev = start_dev(procs, robogene_bin, yarp_env, "--device", "test_motor", "--name", "/m", "--period", "0.1")
    for port in ("/m/rpc:i", "/m/command:i", "/m/state:o", "/m/stateExt:o"):
        assert query(name_server, port), port
    reply = cli("rpc", "/m/rpc:i", input="[get] [axes]\n[get] [prot]\n")
    assert reply.returncode == 0, reply.stderr
    lines = reply.stdout.splitlines()
    assert re.fullmatch(r"Response: \[is\] \[axes\] 4 \[tsta\] \d+ \S+ \[ok\]", lines[0]), lines
    assert lines[1] == "Response: [prot] 1 9 0 [ok]"
    # SIGINT stops it and unregisters every port.
    dev.signal(signal.SIGINT)
    assert dev.wait_exit() == 0
    dev.wait_for_line(r"test_motor closed", stream="err")
    for port in ("/m/rpc:i", "/m/command:i", "/m/state:o", "/m/stateExt:o"):
        assert query(name_server, port) is None, port


def test_from_ini_file_with_groups_and_subdevice(name_server, procs, robogene_bin, yarp_env, tmp_path, cli):
    ini = tmp_path / "head.ini"
    ini.write_text("# a served test_motor\ndevice controlBoard_nws_yarp\nsubdevice test_motor\n"
                   "name /head\naxes 6\n[GENERAL]\nJoints 6\n")
    dev = start_dev(procs, robogene_bin, yarp_env, "--from", str(ini), "--axes", "3")
    reply = cli("rpc", "/head/rpc:i", input="[get] [axes]\n")
    assert re.match(r"Response: \[is\] \[axes\] 3 ", reply.stdout), reply.stdout  # command line wins
    dev.signal(signal.SIGTERM)
    assert dev.wait_exit() == 0
    assert query(name_server, "/head/rpc:i") is None


@pytest.mark.parametrize("wrapper", ["controlBoard_nws_yarp", "controlboardwrapper2"])
def test_subdevice_given_on_the_command_line(name_server, procs, robogene_bin, yarp_env, cli, wrapper):
    dev = start_dev(procs, robogene_bin, yarp_env, "--device", wrapper, "--subdevice", "test_motor",
                    "--axes", "2", "--name", "/sub")
    reply = cli("rpc", "/sub/rpc:i", input="[get] [axes]\n[get] [rgif]\n[set] [torq] [ref] 1 0.5\n"
                                          "[get] [icmd] [cmod] 1\n")
    assert reply.returncode == 0, reply.stderr
    axes, listed, torque, mode = reply.stdout.splitlines()
    assert re.fullmatch(r"Response: \[is\] \[axes\] 2 \[tsta\] \d+ \S+ \[ok\]", axes)  # --axes reached it
    # The wrapper serves the subdevice's interfaces: test_motor's, torque control included.
    names = re.findall(r"\((\w+) \"?[0-9a-f]{16}\"?\)", listed)
    assert names == ["IEncoders", "IPositionControl", "IVelocityControl", "ITorqueControl", "IPidControl",
                     "IControlMode"], listed
    assert torque == "Response: [ok]"
    assert mode.startswith("Response: [is] 1 [torq] [tsta] "), mode
    dev.signal(signal.SIGTERM)
    assert dev.wait_exit() == 0
    dev.wait_for_line(rf"{wrapper} closed", stream="err")
    assert query(name_server, "/sub/rpc:i") is None


@pytest.mark.parametrize("args, message", [
    ((), r"no device given"),
    (("--device", "dragonfly", "--name", "/d"), r"unknown device 'dragonfly' \(known devices: .*test_motor"),
    (("--device", "test_motor"), r"key 'name'|'name'"),
    (("--device", "test_motor", "--name", "/x", "--axes", "100"), r"axes.*100"),
    (("--device", "test_motor", "--name", "/x", "--period", "-1"), r"period"),
    (("--from", "/nonexistent/motor.ini"), r"/nonexistent/motor.ini"),
    (("--from",), r"key 'from': expected a word or a \"string\", got true"),  # not the file "1"
    (("--device", "controlBoard_nws_yarp", "--subdevice", "dragonfly", "--name", "/x"),
     r"unknown device 'dragonfly'"),
    (("--device", "controlBoard_nws_yarp", "--subdevice", "fake_grabber", "--name", "/x"),
     r"^robogene dev: device 'controlBoard_nws_yarp': /x: the device to serve implements none of the "
     r"interfaces of the controlboard service$"),
    (("--device", "frameGrabber_nws_yarp", "--subdevice", "test_motor", "--name", "/x"),
     r"/x: the device to serve implements none of the interfaces of the grabber service"),
    (("--device", "controlBoard_nws_yarp", "--name", "/x"), r"no 'subdevice' key naming the device to serve"),
])
def test_bad_configurations_are_reported(name_server, cli, args, message):
    result = cli("dev", *args)
    assert result.returncode != 0
    assert re.search(message, result.stderr), result.stderr


def test_paper_section_3_3_program_runs_unchanged_against_robogene_dev(name_server, procs, robogene_bin,
                                                                     yarp_env):
    """The README's walkthrough: the same program, local and then remote by configuration only."""
    program = os.path.join(os.path.dirname(robogene_bin), "paper_section_3_3")
    start_dev(procs, robogene_bin, yarp_env, "--device", "test_motor", "--axes", "2", "--name", "/motors")
    for extra in ([], ["--device", "remote_controlboard", "--remote", "/motors", "--local", "/paper"]):
        run = subprocess.run([program, "--seconds", "1", *extra], capture_output=True, text=True,
                             env=yarp_env, timeout=30)
        assert run.returncode == 0, run.stderr
        last = run.stdout.splitlines()[-1]
        m = re.fullmatch(r"t=(\S+) s  joint 0: +(\S+) deg  joint 1: +(\S+) deg", last)
        assert m, run.stdout
        t, j0, j1 = (float(g) for g in m.groups())
        # 5 deg/s after a 0.05 s ramp, less up to one 20 ms state period when remote.
        assert 5 * (t - 0.15) < j0 <= 5 * t + 1e-6, run.stdout
        assert 5 * (t - 0.15) < j1 <= 5 * t + 1e-6, run.stdout


def test_a_camera_is_wrapped_by_the_grabber_server(name_server, procs, robogene_bin, yarp_env, cli):
    dev = start_dev(procs, robogene_bin, yarp_env, "--device", "fake_grabber", "--width", "640", "--height", "480",
                    "--name", "/camera")
    dev.wait_for_line(r"fake_grabber serving on /camera/rpc /camera$", stream="err")
    reply = cli("rpc", "/camera/rpc", input="[get] [rgif]\n")
    assert re.match(r'Response: \[is\] \[rgif\] \(\(IFrameGrabberImage "?\w+"?\) \(IFrameGrabberControls "?\w+"?\)\)',
                    reply.stdout), reply.stdout
    dev.signal(signal.SIGTERM)
    assert dev.wait_exit() == 0
    assert query(name_server, "/camera") is None
