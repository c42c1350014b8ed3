# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Python ports against the C++ command-line tools in other processes: a Python writer read by
`robogene read`, `robogene write` read by Python, a Python RpcServer answered through
`robogene rpc`, and `robogene connect` / `ls` acting on Python ports."""
from __future__ import annotations

import array

import pytest

import robogene

pytestmark = pytest.mark.timeout(60)


def ok(result):
    assert result.returncode == 0, f"exit {result.returncode}\nstdout: {result.stdout}\nstderr: {result.stderr}"
    return result.stdout


def start_cli_reader(procs, robogene_bin, yarp_env, name, *extra):
    proc = procs.start(f"read {name}", [robogene_bin, "read", name, *extra], yarp_env)
    proc.wait_for_line(rf"Port {name} active at tcp://", stream="err")
    return proc


def test_python_writer_to_cli_reader(name_server, network, procs, robogene_bin, yarp_env):
    reader = start_cli_reader(procs, robogene_bin, yarp_env, "/cli/r", "--envelope")
    with robogene.Port("/py/w", network=network) as w:
        w.add_output("/cli/r")
        w.set_envelope(robogene.Stamp(3, 12.5))
        assert w.write(robogene.Bottle.from_text('1 2.5 "hi" [set] (nested 1) {1 2 255}'))
        w.set_envelope(None)
        assert w.write(robogene.Bottle.from_floats(array.array("d", [0.5, -1.0])))
        reader.wait_for_line(r"^3 12\.5 \| 1 2\.5 hi \[set\] \(nested 1\) \{1 2 255\}$")
        reader.wait_for_line(r"^0\.5 -1\.0$")


def test_cli_writer_to_python_reader(name_server, network, cli):
    with robogene.BufferedPort("/py/r", policy="strict", network=network) as r:
        ok(cli("write", "/cli/w", "/py/r", input='hello "big world" 3\n(1 2) [ok]\n'))
        first, info = r.read_with_info(timeout=10)
        assert first.to_python() == ["hello", "big world", 3]
        assert info.sender == "/cli/w"
        assert r.read(timeout=10).to_text() == "(1 2) [ok]"


def test_python_rpc_server_answers_cli_rpc(name_server, network, cli):
    def handler(request, info):
        return [robogene.Value.vocab("is"), *request.to_python(), info.sender]
    with robogene.RpcServer("/py/rpc:i", handler, network=network):
        out = ok(cli("rpc", "/py/rpc:i", input="get axes\n[set] [pos] 1 25.0\n"))
    assert out == ('Response: [is] get axes anon_rpc\n'
                   'Response: [is] [set] [pos] 1 25.0 anon_rpc\n')


def test_cli_connect_and_ls_see_python_ports(name_server, network, cli):
    with robogene.Port("/py/src", network=network) as src, \
            robogene.BufferedPort("/py/dst", network=network) as dst:
        assert ok(cli("connect", "/py/src", "/py/dst")) == "Success: Added connection from /py/src to tcp://py/dst\n"
        assert src.outputs == ["/py/dst"]
        src.write(["via", "cli"])
        assert dst.read(timeout=10).to_text() == "via cli"
        ls = ok(cli("ls"))
        assert "/py/src  tcp://127.0.0.1:" in ls and "  -> /py/dst (tcp)" in ls
        ok(cli("disconnect", "/py/src", "/py/dst"))
        assert src.outputs == []
    assert "/py/src" not in ok(cli("name", "list"))
