# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Starting the command-line tools of both implementations on a private network.

A port is ready once it logs `Port /x active at ...` (YARP 3.5 on stdout, our CLI on stderr): both
register their name before they listen. Connections are observed from outside: the YARP peer's own
log (`Receiving input from /w to /r using tcp`) or admin `[list] [out]`."""
from __future__ import annotations

import re
import subprocess
from pathlib import Path

import interop_net as net_
from interop_peer import PrivateNetwork, robogene_bin, yarp_python, yarp_tool, yarpdev
from interop_procs import Proc, ProcessGroup, run

START_TIMEOUT = 15.0
# YARP 3.5 logs INFO to stdout ("[INFO] |yarp.os.Port|/r| Port /r active at ...") and the companion
# prints "Interrupting..." when stopped; everything else on a tool's stdout is its data.
YARP_LOG = r"^\[(INFO|DEBUG|TRACE|WARNING|ERROR|FATAL)\]|^Interrupting\.\.\.$"
# YARP's tools print with C stdio, which is block-buffered on a pipe: force line buffering.
LINE_BUFFERED = ["stdbuf", "-oL", "-eL"]
HERE = Path(__file__).resolve().parent


class YarpTools:
    def __init__(self, procs: ProcessGroup, net: PrivateNetwork):
        self.procs, self.net = procs, net

    def server(self) -> Proc:
        proc = self._start("yarpserver", [
            yarp_tool("yarpserver"), "--ip", "127.0.0.1", "--socket", str(self.net.ns_port), "--read",
            "--portdb", ":memory:", "--subdb", ":memory:"], cwd=str(self.net.base))
        net_.wait_registered(self.net.ns_port, "/root", START_TIMEOUT)
        return proc

    def _start(self, name: str, argv: list, cwd=None) -> Proc:
        return self.procs.start(name, LINE_BUFFERED + argv, self.net.env, cwd, YARP_LOG)

    def _wait_active(self, proc: Proc, port: str, timeout: float = START_TIMEOUT) -> None:
        """YARP registers a port before it listens; `Port /x active at ...` comes once it listens."""
        proc.wait_output(rf"Port {re.escape(port)} active at ", timeout)

    def read(self, port: str, *extra: str) -> Proc:
        proc = self._start(f"yarp read {port}", [yarp_tool("yarp"), "read", port, *extra])
        self._wait_active(proc, port)
        return proc

    def write(self, port: str, *targets: str) -> Proc:
        proc = self._start(f"yarp write {port}", [yarp_tool("yarp"), "write", port, *targets])
        self._wait_active(proc, port)
        for target in targets:
            proc.wait_output(rf"Sending output from {port} to {target} using", START_TIMEOUT)
        return proc

    def rpc(self, target: str) -> Proc:
        return self._start(f"yarp rpc {target}", [yarp_tool("yarp"), "rpc", target])

    def admin_rpc(self, target: str) -> Proc:
        """`yarp admin rpc`: requests go to the port itself as administrative messages ('a')."""
        return self._start(f"yarp admin rpc {target}", [yarp_tool("yarp"), "admin", "rpc", target])

    def python(self, name: str, script: str, *args: str) -> Proc:
        """A script of tests/interop run by the peer's interpreter (with the SWIG `yarp` module)."""
        return self._start(name, [yarp_python(), str(HERE / script), *args])

    def echo_server(self, port: str) -> Proc:
        proc = self.python(f"yarp echo {port}", "yarp_echo_server.py", port)
        proc.wait_output(r"^ready$", START_TIMEOUT, "stdout")
        self._wait_active(proc, port)
        return proc

    def fake_motors(self, name: str = "/motors", joints: int = 4) -> Proc:
        """yarpdev serving fakeMotionControl through controlboardwrapper2 (the 3.5 network wrapper)."""
        proc = self.dev("--device", "controlboardwrapper2", "--subdevice", "fakeMotionControl",
                        "--name", name, "--GENERAL::Joints", str(joints))
        for suffix in ("rpc:i", "command:i", "state:o", "stateExt:o"):
            self._wait_active(proc, f"{name}/{suffix}", 30)
        # The wrapper's ports are announced before it has attached the subdevice and started.
        proc.wait_output(r"device active in background", 30)
        return proc

    def dev(self, *args: str) -> Proc:
        return self._start("yarpdev", [yarpdev(), *args])

    def cmd(self, *args: str, timeout: float = 20.0, stdin: str = "") -> subprocess.CompletedProcess:
        return run([yarp_tool("yarp"), *args], self.net.env, timeout, stdin)


class RobogeneTools:
    def __init__(self, procs: ProcessGroup, net: PrivateNetwork):
        self.procs, self.net = procs, net
        self.bin = robogene_bin()

    def _wait_active(self, proc: Proc, port: str) -> None:
        """Like YARP, our ports register before they listen and log `Port /x active at ...` once
        they do (on stderr); registration alone would race with the first connection."""
        proc.wait_output(rf"Port {re.escape(port)} active at ", START_TIMEOUT)
        net_.wait_registered(self.net.ns_port, port, START_TIMEOUT)

    def server(self) -> Proc:
        proc = self.procs.start("robogene server", [
            self.bin, "server", "--ip", "127.0.0.1", "--socket", str(self.net.ns_port), "--db", ":memory:"],
            self.net.env)
        net_.wait_registered(self.net.ns_port, "/root", START_TIMEOUT)
        return proc

    def read(self, port: str, *sources: str) -> Proc:
        proc = self.procs.start(f"robogene read {port}", [self.bin, "read", port, *sources], self.net.env)
        self._wait_active(proc, port)
        return proc

    def write(self, port: str, *targets: str) -> Proc:
        proc = self.procs.start(f"robogene write {port}", [self.bin, "write", port, *targets], self.net.env)
        self._wait_active(proc, port)
        return proc

    def rpc(self, target: str, *extra: str) -> Proc:
        return self.procs.start(f"robogene rpc {target}", [self.bin, "rpc", target, *extra], self.net.env)

    def cmd(self, *args: str, timeout: float = 20.0, stdin: str = "") -> subprocess.CompletedProcess:
        return run([self.bin, *args], self.net.env, timeout, stdin)

