# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Child processes for the interop tests: output captured line by line, every wait has a deadline,
every process stopped by its own id when the test ends (whatever the outcome)."""
from __future__ import annotations

import os
import re
import signal
import subprocess
import threading
import time
from typing import Callable, Optional, Sequence


class Proc:
    """One child process (its own session) with stdin fed by the test and stdout/stderr collected."""

    def __init__(self, name: str, argv: Sequence[str], env: dict, cwd: Optional[str] = None,
                 log_pattern: Optional[str] = None):
        self.name = name
        self.argv = list(argv)
        # stdout lines matching log_pattern are the tool's log, not its data (YARP logs INFO to stdout)
        self._log = re.compile(log_pattern) if log_pattern else None
        self._lock = threading.Condition()
        self._out: list[str] = []
        self._err: list[str] = []
        self._popen = subprocess.Popen(
            self.argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
            env=env, cwd=cwd, start_new_session=True)
        self.pid = self._popen.pid
        self._readers = [
            threading.Thread(target=self._pump, args=(self._popen.stdout, self._out), daemon=True),
            threading.Thread(target=self._pump, args=(self._popen.stderr, self._err), daemon=True),
        ]
        for t in self._readers:
            t.start()

    def _pump(self, stream, sink: list) -> None:
        for raw in iter(stream.readline, b""):
            with self._lock:
                sink.append(raw.decode("utf-8", "backslashreplace").rstrip("\r\n"))
                self._lock.notify_all()
        with self._lock:
            self._lock.notify_all()

    # -- output --------------------------------------------------------------------------------
    @property
    def stdout(self) -> list[str]:
        with self._lock:
            return list(self._out)

    @property
    def stderr(self) -> list[str]:
        with self._lock:
            return list(self._err)

    def _data(self) -> list[str]:
        return [l for l in self._out if not (self._log and self._log.search(l))]

    @property
    def data(self) -> list[str]:
        """stdout without the log lines: what the tool printed as its output proper."""
        with self._lock:
            return self._data()

    def describe(self) -> str:
        rc = self._popen.poll()
        state = "running" if rc is None else f"exited with {rc}"
        return (f"[{self.name}] {' '.join(self.argv)} ({state}, pid {self.pid})\n"
                f"  stdout: {self.stdout[-40:]}\n  stderr: {self.stderr[-40:]}")

    def wait_until(self, what: str, ready: Callable[[], bool], timeout: float) -> None:
        """Block until ready() holds (checked on each new output line and every 50 ms) or fail."""
        deadline = time.monotonic() + timeout
        with self._lock:
            while not ready():
                left = deadline - time.monotonic()
                if left <= 0:
                    raise AssertionError(f"timed out after {timeout:.1f} s waiting for {what}\n{self.describe()}")
                self._lock.wait(min(left, 0.05))

    def wait_data(self, count: int, timeout: float) -> list[str]:
        """Wait for count data lines on stdout; returns all of them (possibly more than count)."""
        self.wait_until(f"{count} data lines on stdout", lambda: len(self._data()) >= count, timeout)
        return self.data

    def wait_output(self, pattern: str, timeout: float, stream: str = "both") -> str:
        """Wait for a line matching the regex pattern on stdout, stderr or both; return the line."""
        rx = re.compile(pattern)
        found: list[str] = []

        def ready() -> bool:
            lines = (self._out if stream in ("stdout", "both") else []) + \
                    (self._err if stream in ("stderr", "both") else [])
            for line in lines:
                if rx.search(line):
                    found.append(line)
                    return True
            return False
        self.wait_until(f"output matching {pattern!r} on {stream}", ready, timeout)
        return found[0]

    # -- input and lifetime --------------------------------------------------------------------
    def send(self, line: str) -> None:
        self._popen.stdin.write(line.encode() + b"\n")
        self._popen.stdin.flush()

    def close_stdin(self) -> None:
        if self._popen.stdin and not self._popen.stdin.closed:
            self._popen.stdin.close()

    def running(self) -> bool:
        return self._popen.poll() is None

    def stop(self, grace: float = 5.0) -> None:
        """SIGTERM (YARP tools then unregister their ports), SIGKILL after the grace period."""
        if self._popen.poll() is None:
            try:
                os.killpg(self.pid, signal.SIGTERM)
            except ProcessLookupError:
                pass
            try:
                self._popen.wait(grace)
            except subprocess.TimeoutExpired:
                try:
                    os.killpg(self.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                self._popen.wait(5)
        try:
            self.close_stdin()
        except (BrokenPipeError, OSError):
            pass
        for t in self._readers:
            t.join(2)


def run(argv: Sequence[str], env: dict, timeout: float, stdin: str = "") -> subprocess.CompletedProcess:
    """Run a short command to completion; a hang is a test failure, not a stuck suite."""
    try:
        return subprocess.run(list(argv), input=stdin.encode(), capture_output=True, env=env,
                              timeout=timeout, start_new_session=True)
    except subprocess.TimeoutExpired as e:
        raise AssertionError(f"{' '.join(argv)} did not finish within {timeout} s; "
                             f"stdout={e.stdout!r} stderr={e.stderr!r}") from None


class ProcessGroup:
    """Every process a test starts; stop_all() runs at teardown, newest first."""

    def __init__(self):
        self._procs: list[Proc] = []

    def start(self, name: str, argv: Sequence[str], env: dict, cwd: Optional[str] = None,
              log_pattern: Optional[str] = None) -> Proc:
        proc = Proc(name, argv, env, cwd, log_pattern)
        self._procs.append(proc)
        return proc

    def stop_all(self) -> None:
        for proc in reversed(self._procs):
            proc.stop()
        self._procs.clear()

    def _data(self) -> list[str]:
        return [l for l in self._out if not (self._log and self._log.search(l))]

    @property
    def data(self) -> list[str]:
        """stdout without the log lines: what the tool printed as its output proper."""
        with self._lock:
            return self._data()

    def describe(self) -> str:
        return "\n".join(p.describe() for p in self._procs)
