# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Cameras across languages on real ports: a fake_grabber opened in this Python process, served
by the bound GrabberNws and read by the C++ tools (`robogene read`, remote_grabber inside
`robogene dev`) and by remote_grabber opened from Python, which also reads the `robogene dev`
camera server; and the image decoder's refusals (robogene.dev.decode_image, the C++ codec)."""
from __future__ import annotations

import re
import time

import pytest

from robogene import Bottle, Network, Value, vocab
from robogene import Error
from robogene.dev import (CameraFeature, DeviceDriver, FeatureMode, GrabberNws, IFrameGrabberControls,
                          IFrameGrabberImage, ImageError, ImageRgb, PolyDriver, Property, RemoteGrabber, decode_image,
                          encode_image)

pytestmark = pytest.mark.timeout(90)

RATE = 30.0


def pattern_frame(image: ImageRgb) -> int:
    """Asserts that `image` is a frame of fake_grabber's pattern (red rises by 1 along a row,
    green by 1 down a column, blue a 16-pixel checkerboard flipping every 8 frames); returns its
    frame number mod 256 (the green of the top-left pixel)."""
    w, h = image.width, image.height
    n = image.pixels[1]
    red = bytes((2 * n + x) % 256 for x in range(w)) * h
    green = b"".join(bytes(((n + y) % 256,)) * w for y in range(h))
    blue_rows = [bytes(200 if (x // 16 + parity) % 2 else 40 for x in range(w)) for parity in (0, 1)]
    blue = b"".join(blue_rows[(y // 16 + (n % 16) // 8) % 2] for y in range(h))
    assert bytes(image.pixels[0::3]) == red, "red does not rise by 1 along each row"
    assert bytes(image.pixels[1::3]) == green, "green does not rise by 1 down each column"
    assert bytes(image.pixels[2::3]) == blue, "blue is not the checkerboard"
    return n


def check_stream(device: PolyDriver, width: int, height: int) -> float:
    """Checks a remote camera's size, three consecutive frames, and returns its frame rate over 2 s."""
    frames = device.view(IFrameGrabberImage)
    assert (frames.width(), frames.height()) == (width, height)
    previous = None
    for _ in range(3):
        image = frames.getImage()
        assert image is not None, "no frame within the remote_grabber's timeout"
        assert (image.width, image.height) == (width, height)
        n = pattern_frame(image)
        assert n != previous, "the frames do not move on"
        previous = n
    remote = device.view(RemoteGrabber)
    before, start = remote.frames_received(), time.monotonic()
    time.sleep(2.0)
    return (remote.frames_received() - before) / (time.monotonic() - start)


def assert_paced(rate: float) -> None:
    """The stream keeps flowing and is paced by the camera's frame rate, never faster. The lower bound
    is loose on purpose: a loaded 2-core CI machine slows the Python camera, which is not a fault."""
    assert RATE * 0.25 <= rate <= RATE * 1.25, rate


def check_controls(controls: IFrameGrabberControls) -> None:
    assert controls.setFeature(CameraFeature.SHUTTER, 0.25) is True
    assert controls.getFeature(CameraFeature.SHUTTER) == 0.25
    assert controls.hasFeature(CameraFeature.SHUTTER) is True
    assert controls.hasFeature(CameraFeature.FOCUS) is False
    assert controls.setActive(CameraFeature.EXPOSURE, False) is True
    assert controls.getActive(CameraFeature.EXPOSURE) is False
    assert controls.setMode(CameraFeature.GAIN, FeatureMode.AUTOMATIC) is True
    assert controls.getMode(CameraFeature.GAIN) == FeatureMode.AUTOMATIC
    assert controls.setFeature(CameraFeature.FOCUS, 0.5) is False  # fake_grabber has no focus
    assert controls.getFeature(CameraFeature.FOCUS) is None


def served(name_server, name: str) -> Property:
    return Property.from_dict({"name": name, "server": name_server.address})


def python_camera(width: int, height: int, rate: float = RATE) -> PolyDriver:
    camera = PolyDriver(Property.from_dict({"device": "fake_grabber", "width": width, "height": height,
                                            "framerate": rate}))
    assert camera.is_valid(), camera.last_error
    return camera


def remote(name_server, remote_name: str, local: str) -> PolyDriver:
    device = PolyDriver(Property.from_dict({"device": "remote_grabber", "remote": remote_name, "local": local,
                                            "server": name_server.address}))
    assert device.is_valid(), device.last_error
    return device


def test_a_python_camera_read_by_the_python_remote_grabber(name_server):
    network = Network(name_server.address)
    with python_camera(640, 480) as camera:
        with GrabberNws(camera.view(DeviceDriver), served(name_server, "/pycam")) as server:
            assert server.port_names() == ["/pycam/rpc", "/pycam"]
            with remote(name_server, "/pycam", "/viewer") as device:
                rate = check_stream(device, 640, 480)
                assert_paced(rate)
                check_controls(device.view(IFrameGrabberControls))
                # The controls reached the Python device.
                assert camera.view(IFrameGrabberControls).getFeature(CameraFeature.SHUTTER) == 0.25
            assert network.query("/viewer") is None and network.query("/viewer/rpc_client") is None
    assert network.query("/pycam") is None and network.query("/pycam/rpc") is None


def test_a_python_camera_answers_on_both_ports_as_yarp_3(name_server):
    """The shapes of YARP 3.5's frame grabbers, with a set answered as YARP 3.12.3 answers it; both
    ports say they are Robogene's (server_identity), in the reply to the admin [prop] [get]."""
    network = Network(name_server.address)
    with python_camera(64, 48) as camera:
        with GrabberNws(camera.view(DeviceDriver), served(name_server, "/pycam")):
            for port in ("/pycam/rpc", "/pycam"):  # YARP's remote_grabber asks the image port
                assert network.rpc(port, Bottle.from_text("[fgi] [get] [w]")).to_text() == "[fgi] [w] [is] 64"
                assert network.rpc(port, Bottle.from_text("[fgc] [set] [feat] 7 0.25")).to_text() == "[fgc] [set] 1"
                assert network.rpc(port, Bottle.from_text("[fgc] [get] [feat] 7")).to_text() == \
                    "[fgc] [feat] [is] 0.25"
                assert network.rpc(port, Bottle.from_text("[fgc] [set] [feat] 7 2.0")).to_text() == "[fgc] [set] 0"
                assert network.rpc(port, Bottle.from_text("[fgc] [bogus] [feat] 7")).to_text() == "[nak]"
                assert network.admin(port, Bottle.from_text('[prop] [get] robogene_service')).to_text() == "grabber"


def test_cpp_tools_read_a_python_camera(name_server, procs, robogene_bin, yarp_env):
    """`robogene read` prints the Python server's images; the C++ remote_grabber, inside
    `robogene dev`, relays them (and the controls) to a Python client."""
    network = Network(name_server.address)
    with python_camera(8, 4) as small:
        with GrabberNws(small.view(DeviceDriver), served(name_server, "/small")):
            reader = procs.start("robogene read", [robogene_bin, "read", "/show", "/small", "--envelope"], yarp_env)
            reader.wait_for_line(r"\[mat\]")
            line = reader.lines_matching(r"\[mat\]")[0]
            m = re.fullmatch(r"(\d+) (\S+) \| \[mat\] \[rgb\] \(3 96 65544 8 4\) \{([\d ]+)\}", line)
            assert m, line
            assert abs(float(m.group(2)) - time.time()) < 10
            wire = bytes(int(b) for b in m.group(3).split())
            rows = [wire[r * 24:(r + 1) * 24] for r in range(4)]
            image = ImageRgb(8, 4, bytearray(b"".join(reversed(rows))))  # bit 16: bottom row first
            pattern_frame(image)
    with python_camera(640, 480) as camera:
        with GrabberNws(camera.view(DeviceDriver), served(name_server, "/pycam")):
            relay = procs.start("robogene dev", [robogene_bin, "dev", "--device", "remote_grabber", "--remote", "/pycam",
                                                 "--local", "/relay", "--name", "/relay/cam"], yarp_env)
            relay.wait_for_line(r"serving on ", stream="err")
            with remote(name_server, "/relay/cam", "/viewer") as device:
                rate = check_stream(device, 640, 480)
                assert_paced(rate)
                assert device.view(IFrameGrabberControls).setFeature(CameraFeature.SHUTTER, 0.75) is True
                assert camera.view(IFrameGrabberControls).getFeature(CameraFeature.SHUTTER) == 0.75
                assert device.view(IFrameGrabberControls).getFeature(CameraFeature.SHUTTER) == 0.75
            assert relay.stop() == 0


def test_the_python_remote_grabber_reads_the_cpp_camera_server(name_server, procs, robogene_bin, yarp_env):
    dev = procs.start("robogene dev", [robogene_bin, "dev", "--device", "fake_grabber", "--width", "640",
                                       "--height", "480", "--framerate", str(RATE), "--name", "/cam"], yarp_env)
    dev.wait_for_line(r"serving on ", stream="err")
    with remote(name_server, "/cam", "/viewer") as device:
        rate = check_stream(device, 640, 480)
        assert_paced(rate)
        check_controls(device.view(IFrameGrabberControls))


def test_the_python_remote_grabber_reports_an_absent_server(name_server):
    device = PolyDriver()
    assert not device.open(Property.from_dict({"device": "remote_grabber", "remote": "/nobody", "local": "/viewer",
                                               "server": name_server.address}))
    assert "/nobody/rpc" in device.last_error
    assert Network(name_server.address).query("/viewer/rpc_client") is None


def test_the_python_camera_server_refuses_a_device_without_a_camera(name_server):
    with PolyDriver(Property.from_dict({"device": "test_motor", "axes": 1})) as motor:
        with pytest.raises(Error, match="/x: the device to serve implements none of the interfaces of the "
                                        "grabber service"):
            GrabberNws(motor.view(DeviceDriver), served(name_server, "/x"))
    assert Network(name_server.address).query("/x") is None


def image_message(header, blob: bytes = b"\0" * 96, code: str = "rgb") -> Bottle:
    b = Bottle()
    b.add(Value.vocab(vocab("mat")))
    b.add(Value.vocab(vocab(code)))
    b.add(Value.list([Value.int32(n) if isinstance(n, int) else Value.string(n) for n in header]))
    b.add(Value.blob(blob))
    return b


@pytest.mark.parametrize("message, reason", [
    (Bottle.from_text("[mat] [rgb]"), "not an image: expected [mat] <pixel code> (header) {pixels}, got 2 items"),
    (image_message((3, 96, 8 | 1 << 16, 8, 4), code="mono"), "pixel code [mono] is not [rgb]"),
    (image_message((3, 96, 8, 8)), "image header is not a list of 5 integers: (3 96 8 8)"),
    (image_message((3, 96, "eight", 8, 4)), "image header field 2 is not an integer: eight"),
    (image_message((1, 96, 8, 8, 4)), "image depth 1 is not 3 (RGB)"),
    (image_message((3, 96, 0, 8, 4)), "image size 8x4 or quantum 0 is out of range"),
    (image_message((3, 96, 8, -8, 4)), "image size -8x4 or quantum 8 is out of range"),
    (image_message((3, 96, 8, 8, 4), b"\0" * 95),
     "image of 8x4 with quantum 8 needs 96 pixel bytes, header says 96, blob has 95"),
    (image_message((3, 100, 8, 8, 4)), "image of 8x4 with quantum 8 needs 96 pixel bytes, header says 100, blob has 96"),
])
def test_decode_image_refuses_a_malformed_image_with_its_reason(message, reason):
    with pytest.raises(ImageError) as refused:
        decode_image(message)
    assert str(refused.value) == reason


def test_decode_image_reads_both_row_orders():
    image = ImageRgb()
    image.resize(5, 3)  # 15 bytes a row, padded to 16 on the wire
    image.pixels = bytes(range(45))
    message = encode_image(image)
    assert message[2].to_text() == f"(3 48 {8 | 1 << 16} 5 3)"
    assert decode_image(message) == image
    # Bit 16 clear (a YARP Python image): the rows come top row first.
    top_first = image_message((3, 48, 8, 5, 3), message[3].as_bytes())
    assert decode_image(top_first).pixels == b"".join(bytes(image.pixels[r * 15:(r + 1) * 15]) for r in (2, 1, 0))
