# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Devices across languages on real ports: the paper's section 3.3 in Python through a C++
`robogene dev` server, and a test_motor opened in this Python process, served by the bound
ControlboardNws and driven by the C++ section 3.3 program (remote_controlboard) in another one."""
from __future__ import annotations

import time

import pytest

import paper_program

from robogene import Bottle, Network, RpcClient
from robogene.dev import DeviceDriver, IEncoders, IPositionControl, IVelocityControl, PolyDriver, Property
from robogene.dev import ControlboardNws

pytestmark = pytest.mark.timeout(60)


def section_3_3(device: PolyDriver):
    """The paper's section 3.3, in Python; returns the encoders 0.5 s later and the time taken."""
    ipos = device.view(IPositionControl)
    ivel = device.view(IVelocityControl)
    start = time.monotonic()
    ipos.setRefAcceleration(0, 100)
    ipos.setRefSpeed(0, 5)
    ipos.positionMove(0, 40)
    ivel.setRefAcceleration(1, 100)
    ivel.velocityMove(1, 5)
    time.sleep(0.5)
    encoders = device.view(IEncoders).getEncoders()
    return encoders, time.monotonic() - start


def test_python_section_3_3_through_a_cpp_server(name_server, procs, robogene_bin, yarp_env):
    dev = procs.start("robogene dev", [robogene_bin, "dev", "--device", "test_motor", "--axes", "2",
                                       "--name", "/motors"], yarp_env)
    dev.wait_for_line(r"serving on ", stream="err")
    with PolyDriver(Property.from_dict({"device": "remote_controlboard", "remote": "/motors",
                                        "local": "/pyclient", "server": name_server.address})) as device:
        assert device.is_valid(), device.last_error
        encoders, elapsed = section_3_3(device)
        assert len(encoders) == 2
        for value in encoders:
            assert 5 * (0.5 - 0.1) < value <= 5 * elapsed + 1e-9, encoders
        assert device.view(IPositionControl).checkMotionDone(0) is False


def test_remote_controlboard_in_python_reports_an_absent_server(name_server):
    device = PolyDriver()
    assert not device.open(Property.from_dict({"device": "remote_controlboard", "remote": "/nobody",
                                               "local": "/pyclient", "server": name_server.address}))
    assert "/nobody/rpc:i" in device.last_error


def test_a_device_served_from_python_to_the_cpp_section_3_3_program(name_server, robogene_bin, yarp_env):
    network = Network(name_server.address)
    with PolyDriver(Property.from_dict({"device": "test_motor", "axes": 2})) as motor:
        with ControlboardNws(motor.view(DeviceDriver), Property.from_dict({"name": "/pymotors",
                                                                            "server": name_server.address})) as server:
            assert server.port_names() == ["/pymotors/rpc:i", "/pymotors/command:i", "/pymotors/state:o",
                                           "/pymotors/stateExt:o"]
            paper_program.run_against(robogene_bin, yarp_env, "/pymotors", 1)
            # The velocity move came on the command port (udp), the rest by RPC: the device served from Python has them.
            with RpcClient(server="/pymotors/rpc:i", network=network) as client:
                reply = client.call(Bottle.from_text("[get] [vmo] 1"))
                assert reply.to_text().startswith("[is] [vmo] 5.0 [tsta] ")
    assert network.query("/pymotors/rpc:i") is None
