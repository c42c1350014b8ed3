# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Shared fixtures for the Python tests that drive the real `robogene` executable.

* ``robogene_bin``  path of the CLI: $ROBOGENE_BIN, else <repo>/build/bin/robogene.
* ``yarp_env``      a private environment (YARP_CONFIG_HOME & co. in the test's tmp dir), so a
                    test never reads or writes the user's yarp.conf.
* ``procs``         starts child processes in their own sessions and stops each one (by its pid)
                    when the test ends, whatever the outcome; every wait has a deadline.
* ``name_server``   a running `robogene server` on a free port with a private database;
                    ``start_name_server(...)`` starts more (or restarts) with chosen options.
* ``cli``           runs one `robogene ...` command against that environment, with a timeout.
* ``fake_port``     a minimal port in Python (answers the tcp handshake and acks), for tests
                    that need something alive at a registered address.
* ``network``       a robogene.Network for that name server (the binding's own client).
* ``python_yarp_env`` points this process's YARP_CONFIG_HOME & co. at the test's private ones.
"""
from __future__ import annotations

import os
import re
import signal
import socket
import struct
import subprocess
import threading
import time
from pathlib import Path
from typing import Callable, Optional, Sequence

import pytest

ROOT = Path(__file__).resolve().parents[2]
START_TIMEOUT = 10.0


def robogene_bin() -> str:
    path = os.environ.get("ROBOGENE_BIN") or str(ROOT / "build" / "bin" / "robogene")
    if not os.access(path, os.X_OK):
        pytest.fail(f"robogene executable not found at {path} (build it, or set ROBOGENE_BIN)")
    return path


@pytest.fixture(scope="session", name="robogene_bin")
def robogene_bin_fixture() -> str:
    return robogene_bin()


class Proc:
    """A child process in its own session; stdout and stderr collected line by line."""

    def __init__(self, name: str, argv: Sequence[str], env: dict, stdin_data: Optional[bytes] = None):
        self.name = name
        self.argv = list(argv)
        self._cond = threading.Condition()
        self.out: list[str] = []
        self.err: list[str] = []
        self._open_streams = 2
        self.popen = subprocess.Popen(self.argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                      stderr=subprocess.PIPE, env=env, start_new_session=True)
        self.pid = self.popen.pid
        for stream, sink in ((self.popen.stdout, self.out), (self.popen.stderr, self.err)):
            threading.Thread(target=self._pump, args=(stream, sink), daemon=True).start()
        if stdin_data is not None:
            self.send(stdin_data)

    def _pump(self, stream, sink: list) -> None:
        for raw in iter(stream.readline, b""):
            with self._cond:
                sink.append(raw.decode("utf-8", "backslashreplace").rstrip("\r\n"))
                self._cond.notify_all()
        with self._cond:
            self._open_streams -= 1
            self._cond.notify_all()

    def send(self, data: bytes | str) -> None:
        if isinstance(data, str):
            data = data.encode()
        self.popen.stdin.write(data)
        self.popen.stdin.flush()

    def close_stdin(self) -> None:
        self.popen.stdin.close()

    def wait_for_line(self, pattern: str, timeout: float = START_TIMEOUT, stream: str = "out") -> re.Match:
        """Waits until a line of stdout (or stderr) matches `pattern`; fails naming what was seen."""
        regex = re.compile(pattern)
        sink = self.out if stream == "out" else self.err
        deadline = time.monotonic() + timeout
        with self._cond:
            while True:
                for line in sink:
                    m = regex.search(line)
                    if m:
                        return m
                left = deadline - time.monotonic()
                if left <= 0 or (self._open_streams == 0 and self.popen.poll() is not None):
                    raise AssertionError(
                        f"{self.name}: no line matching {pattern!r} within {timeout}s "
                        f"(exit {self.popen.poll()})\n{self.describe()}")
                self._cond.wait(min(left, 0.1))

    def lines_matching(self, pattern: str) -> list[str]:
        regex = re.compile(pattern)
        with self._cond:
            return [l for l in self.out if regex.search(l)]

    def wait_exit(self, timeout: float = START_TIMEOUT) -> int:
        return self.popen.wait(timeout=timeout)

    def signal(self, sig: int) -> None:
        if self.popen.poll() is None:
            os.kill(self.pid, sig)

    def stop(self, timeout: float = 5.0) -> Optional[int]:
        """SIGTERM, then SIGKILL if it does not exit in time; returns the exit status."""
        if self.popen.poll() is None:
            os.kill(self.pid, signal.SIGTERM)
            try:
                self.popen.wait(timeout=timeout)
            except subprocess.TimeoutExpired:
                os.kill(self.pid, signal.SIGKILL)
                self.popen.wait(timeout=timeout)
        return self.popen.returncode

    def describe(self) -> str:
        with self._cond:
            return (f"--- {self.name} ({' '.join(self.argv)}) pid {self.pid} exit {self.popen.poll()}\n"
                    "stdout:\n  " + "\n  ".join(self.out) + "\nstderr:\n  " + "\n  ".join(self.err))


class ProcessGroup:
    def __init__(self) -> None:
        self.procs: list[Proc] = []

    def start(self, name: str, argv: Sequence[str], env: dict, stdin_data: Optional[bytes] = None) -> Proc:
        proc = Proc(name, argv, env, stdin_data)
        self.procs.append(proc)
        return proc

    def stop_all(self) -> None:
        for proc in reversed(self.procs):
            try:
                proc.stop()
            except Exception:  # keep stopping the others
                pass

    def describe(self) -> str:
        return "\n".join(p.describe() for p in self.procs)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    rep = outcome.get_result()
    setattr(item, f"rep_{rep.when}", rep)


@pytest.fixture
def procs(request):
    group = ProcessGroup()
    yield group
    rep = getattr(request.node, "rep_call", None)
    if rep is not None and rep.failed and group.procs:
        print("\n--- processes of the failed test ---\n" + group.describe())
    group.stop_all()


@pytest.fixture
def yarp_env(tmp_path) -> dict:
    env = dict(os.environ)
    for var, sub in (("YARP_CONFIG_HOME", "config"), ("YARP_DATA_HOME", "data"),
                     ("YARP_CACHE_HOME", "cache"), ("YARP_RUNTIME_DIR", "runtime")):
        path = tmp_path / "yarp" / sub
        path.mkdir(parents=True, exist_ok=True)
        env[var] = str(path)
    env.pop("YARP_NAMESPACE", None)
    return env


class NameServer:
    """A `robogene server` child process and where it listens."""

    def __init__(self, proc: Proc, host: str, port: int, db: str):
        self.proc, self.host, self.port, self.db = proc, host, port, db

    @property
    def address(self) -> str:
        return f"{self.host}:{self.port}"


@pytest.fixture
def start_name_server(procs, yarp_env, robogene_bin, tmp_path) -> Callable[..., NameServer]:
    def start(*extra: str, port: int = 0, db: Optional[str] = None) -> NameServer:
        db = db or str(tmp_path / "names.db")
        proc = procs.start("robogene server", [robogene_bin, "server", "--ip", "127.0.0.1", "--socket", str(port),
                                               "--db", db, *extra], yarp_env)
        m = proc.wait_for_line(r"listening at tcp://([\d.]+):(\d+)/")
        return NameServer(proc, m.group(1), int(m.group(2)), db)
    return start


@pytest.fixture
def name_server(start_name_server) -> NameServer:
    return start_name_server()


@pytest.fixture
def cli(yarp_env, robogene_bin) -> Callable[..., subprocess.CompletedProcess]:
    """cli("name", "query", "/x", input="...", timeout=10) -> CompletedProcess with text output."""
    def run(*args: str, input: Optional[str] = None, timeout: float = 15.0) -> subprocess.CompletedProcess:
        return subprocess.run([robogene_bin, *args], input=input, capture_output=True, text=True,
                              env=yarp_env, timeout=timeout)
    return run


class FakePort:
    """Listens on 127.0.0.1 and behaves like a YARP port towards a tcp peer: answers the carrier
    header with "YA <port> RP" and acks every indexed message. Enough to be judged alive."""

    def __init__(self) -> None:
        self.sock = socket.socket()
        self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(16)
        self.port = self.sock.getsockname()[1]
        self.connections = 0
        self._stop = False
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self) -> None:
        while not self._stop:
            try:
                conn, _ = self.sock.accept()
            except OSError:
                return
            self.connections += 1
            threading.Thread(target=self._talk, args=(conn,), daemon=True).start()

    @staticmethod
    def _read(conn, n: int) -> bytes:
        data = b""
        while len(data) < n:
            chunk = conn.recv(n - len(data))
            if not chunk:
                raise EOFError
            data += chunk
        return data

    def _talk(self, conn) -> None:
        try:
            conn.settimeout(5)
            self._read(conn, 8)
            (length,) = struct.unpack("<i", self._read(conn, 4))
            self._read(conn, length)
            conn.sendall(b"YA" + struct.pack("<i", self.port) + b"RP")
            while True:
                self._read(conn, 8)
                counts = self._read(conn, 10)
                lengths = struct.unpack(f"<{counts[0] + counts[1]}i", self._read(conn, 4 * (counts[0] + counts[1])))
                body = self._read(conn, sum(lengths))
                conn.sendall(b"YA\0\0\0\0RP")
                if body[5:6] == b"\0" and body[8:9] == b"q":
                    return
        except (OSError, EOFError, struct.error):
            pass
        finally:
            conn.close()

    def close(self) -> None:
        self._stop = True
        try:
            self.sock.shutdown(socket.SHUT_RDWR)  # wakes the accept() thread; close alone does not
        except OSError:
            pass
        self.sock.close()


@pytest.fixture
def fake_port():
    made: list[FakePort] = []

    def make() -> FakePort:
        p = FakePort()
        made.append(p)
        return p
    yield make
    for p in made:
        p.close()


@pytest.fixture
def network(name_server):
    """A robogene.Network (the Python name-server client) for the test's `robogene server`."""
    import robogene
    return robogene.Network(name_server.address)


@pytest.fixture
def python_yarp_env(yarp_env, monkeypatch) -> dict:
    """Makes this test process read the test's private YARP configuration, as its CLI children do
    (so `robogene.Port("/x")` finds the name server through yarp.conf)."""
    for var in ("YARP_CONFIG_HOME", "YARP_DATA_HOME", "YARP_CACHE_HOME", "YARP_RUNTIME_DIR"):
        monkeypatch.setenv(var, yarp_env[var])
    monkeypatch.delenv("YARP_NAMESPACE", raising=False)
    return yarp_env
