# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Cameras across implementations: YARP 3.5's remote_grabber (re-served by its grabberDual) reading
images and controls from `robogene dev --device fake_grabber`, and our remote_grabber (re-served
by our grabberDual) reading images from YARP's grabberDual over fakeFrameGrabber. The frames are
read and the requests sent by YARP's own Python module (tests/interop/yarp_grabber_probe.py)."""
import re

import pytest

import interop_net as net_
from interop_peer import robogene_bin

pytestmark = pytest.mark.timeout(120)


def probe(yarp, image_port, local, rpc_port, *requests):
    proc = yarp.python("grabber probe", "yarp_grabber_probe.py", image_port, local, rpc_port, *requests)
    proc.wait_until("done", lambda: "done" in proc.stdout or not proc.running(), 60)
    assert "done" in proc.stdout, proc.describe()
    frames = [l.split()[1:] for l in proc.stdout if l.startswith("frame ")]
    replies = [l[len("reply "):] for l in proc.stdout if l.startswith("reply")]
    return [[int(x) for x in f] for f in frames], replies


def test_yarps_remote_grabber_reads_robogene_fake_grabber(yarpserver, yarp, procs, net):
    dev = procs.start("robogene dev", [robogene_bin(), "dev", "--device", "fake_grabber", "--width", "640",
                                       "--height", "480", "--name", "/interop/cam"], net.env)
    dev.wait_output(r"serving on /interop/cam/rpc /interop/cam$", 15)
    # YARP's remote_grabber: images from our /interop/cam, requests to /interop/cam itself.
    proxy = yarp.dev("--device", "grabberDual", "--subdevice", "remote_grabber", "--remote", "/interop/cam",
                     "--local", "/interop/client", "--name", "/interop/proxy")
    proxy.wait_output(r"Port /interop/proxy/rpc active at ", 30)
    net_.wait_registered(net.ns_port, "/interop/proxy", 15)
    frames, replies = probe(yarp, "/interop/proxy", "/interop/probe", "/interop/proxy/rpc",
                            "[fgc] [set] [feat] 7 0.25", "[fgc] [get] [feat] 7", "[fgc] [has] [feat] 7",
                            "[fgc] [has] [feat] 10", "[fgc] [set] [mode] 7 2", "[fgc] [get] [mode] 7")
    # fake_grabber's pattern: red x + 2n, green y + n, so red steps by 1 along a row, green down a column.
    assert frames and all(f[:4] == [640, 480, 1, 1] and f[4] > 0 for f in frames), frames
    set_feat, get_feat, has_shutter, has_focus, set_mode, get_mode = replies
    # Our server answers a set with [fgc] [set] 1, as YARP 3.12.3's do. YARP 3.5's remote_grabber reports
    # any set that gets a reply as done, and its grabberDual answers every set with [nak] (its
    # responder leaves the reply empty, which DeviceResponder turns into [nak]): the gets that
    # follow read the values back through the same chain.
    assert set_feat == "[nak]" and get_feat == "[fgc] [feat] [is] 0.25"
    assert has_shutter == "[fgc] [has] [feat] 1952540006 1" and has_focus == "[fgc] [has] [feat] 1952540006 0"
    assert set_mode == "[nak]" and get_mode == "[fgc] [mode] [is] 2"


def test_our_remote_grabber_reads_yarps_grabber_server(yarpserver, yarp, ours, procs, net):
    cam = yarp.dev("--device", "grabberDual", "--subdevice", "fakeFrameGrabber", "--width", "640", "--height",
                   "480", "--name", "/interop/cam", "--fakeFrameGrabber_rpc_port", "/interop/fake/rpc")
    # The image port is announced before the grabber thread runs; wait for the device itself.
    cam.wait_output(r"device active in background", 30)
    dev = procs.start("robogene dev", [robogene_bin(), "dev", "--device", "grabberDual", "--subdevice",
                                       "remote_grabber", "--remote", "/interop/cam", "--local", "/interop/ours",
                                       "--name", "/interop/ourproxy"], net.env)
    dev.wait_output(r"serving on ", 20)
    frames, replies = probe(yarp, "/interop/ourproxy", "/interop/probe", "/interop/ourproxy/rpc",
                            "[fgi] [get] [w]", "[fgi] [get] [h]", "[fgc] [get] [feat] 7")
    # fakeFrameGrabber's default `line` mode: 640x480 frames with a drawn line. YARP 3.5's
    # grabberDual writes a shallow copy of the buffer the grabber draws into next, so a frame can be
    # caught between `zero()` and the line (its very first frame always is): one of two must show it.
    assert len(frames) == 2 and all(f[:2] == [640, 480] for f in frames), frames
    assert any(f[4] > 0 for f in frames), frames
    width, height, feature = replies
    # grabberDual does not answer [fgi] [get] [w]: our client takes the size from its frames.
    assert (width, height) == ("[fgi] [w] [is] 640", "[fgi] [h] [is] 480")
    # YARP 3.5's fakeFrameGrabber fails every control; grabberDual says so with a trailing
    # "command not recognized", which our client reports as a failure.
    assert feature == "[nak]"
    listed = yarp.cmd("admin", "rpc", "/interop/cam", stdin="[list] [out]\n")
    assert re.search(rb"/interop/ours\b", listed.stdout), listed
    # YARP's grabberDual logs "Command not recognized" for our fingerprint request: it never gets one.
    assert not any("rgif" in line for line in cam.stdout + cam.stderr), cam.describe()
