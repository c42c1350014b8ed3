# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Ports in a separate Python process: Ctrl-C ends a blocking read, and a script that exits with
ports still open (one of them with a callback) ends promptly and unregisters them."""
from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest

pytestmark = pytest.mark.timeout(60)


def run_script(body: str, env: dict) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-c", textwrap.dedent(body)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=env, start_new_session=True)


def wait_for_output(proc: subprocess.Popen, expected: str) -> None:
    line = proc.stdout.readline()  # '' if the script died first (the test timeout bounds the rest)
    assert line.strip() == expected, f"got {line!r}; stderr: {proc.stderr.read() if proc.poll() is not None else ''}"


def test_ctrl_c_interrupts_a_blocking_read(name_server, network, yarp_env):
    proc = run_script(f"""
        import robogene
        p = robogene.Port("/py/sigint", network=robogene.Network("{name_server.address}"))
        print("ready", flush=True)
        try:
            p.read()
        except KeyboardInterrupt:
            print("interrupted", flush=True)
        p.close()
    """, yarp_env)
    try:
        wait_for_output(proc, "ready")
        time.sleep(0.3)
        start = time.monotonic()
        os.kill(proc.pid, signal.SIGINT)
        assert proc.wait(timeout=10) == 0, proc.stderr.read()
        assert proc.stdout.read().strip() == "interrupted"
        assert time.monotonic() - start < 5
        assert network.query("/py/sigint") is None
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()


def test_exit_with_open_ports_and_a_running_callback(name_server, network, yarp_env):
    proc = run_script(f"""
        import time, robogene
        net = robogene.Network("{name_server.address}")
        reader = robogene.BufferedPort("/py/left:i", network=net)
        reader.on_read(lambda b, info: time.sleep(0.2))
        writer = robogene.Port("/py/left:o", network=net)
        writer.add_output("/py/left:i")
        writer.write([1])
        server = robogene.RpcServer("/py/left:rpc", lambda r, i: r, network=net)
        print("ready", flush=True)
        # exits with everything open: the atexit hook closes and unregisters them
    """, yarp_env)
    try:
        wait_for_output(proc, "ready")
        assert proc.wait(timeout=15) == 0, proc.stderr.read()
        for name in ("/py/left:i", "/py/left:o", "/py/left:rpc"):
            assert network.query(name) is None, f"{name} still registered"
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
