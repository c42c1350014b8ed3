# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""`python -m robogene.dev`, the Python `robogene dev`, as a process of its own: a Python test_motor
it serves is driven by the paper's C++ program, a camera it serves is read by `robogene read`, the
wrapper devices take their subdevice from an .ini file, SIGTERM closes and unregisters, and bad
input is named."""
import signal
import sys

import pytest

from robogene import Network

import paper_program

pytestmark = pytest.mark.timeout(60)


def pydev(procs, env, *args: str):
    return procs.start("python -m robogene.dev", [sys.executable, "-m", "robogene.dev", *args], env)


def run_pydev(env, *args: str):
    import subprocess
    return subprocess.run([sys.executable, "-m", "robogene.dev", *args], capture_output=True, text=True, env=env,
                          timeout=30)


def test_served_test_motor_runs_the_papers_program_and_closes_on_sigterm(name_server, procs, robogene_bin, yarp_env):
    dev = pydev(procs, yarp_env, "--server", name_server.address, "--device", "test_motor", "--name", "/pymotors")
    dev.wait_for_line(r"^robogene dev: test_motor serving on /pymotors/rpc:i /pymotors/command:i /pymotors/state:o "
                      r"/pymotors/stateExt:o$", stream="err")
    paper_program.run_against(robogene_bin, yarp_env, "/pymotors", 1)
    dev.signal(signal.SIGTERM)
    assert dev.wait_exit() == 0, dev.describe()
    dev.wait_for_line(r"^robogene dev: test_motor closed$", stream="err")
    network = Network(name_server.address)
    assert all(network.query(f"/pymotors/{p}") is None for p in ("rpc:i", "command:i", "state:o", "stateExt:o"))


def test_wrapper_device_from_an_ini_file(name_server, procs, cli, yarp_env, tmp_path):
    ini = tmp_path / "board.ini"
    ini.write_text("device controlboardwrapper2\nsubdevice test_motor\naxes 2\nname /fromini\n")
    dev = pydev(procs, yarp_env, "--server", name_server.address, "--from", str(ini), "--name", "/override")
    dev.wait_for_line(r"controlboardwrapper2 serving on /override/rpc:i ", stream="err")
    reply = cli("rpc", "/override/rpc:i", input="[get] [axes]\n")
    assert reply.returncode == 0 and "[is] [axes] 2" in reply.stdout, reply
    dev.signal(signal.SIGINT)
    assert dev.wait_exit() == 0, dev.describe()


def test_served_camera_is_read_by_the_cpp_tool(name_server, procs, robogene_bin, yarp_env):
    dev = pydev(procs, yarp_env, "--server", name_server.address, "--device", "fake_grabber", "--width", "8",
                "--height", "4", "--name", "/pycam")
    dev.wait_for_line(r"fake_grabber serving on /pycam/rpc /pycam$", stream="err")
    reader = procs.start("robogene read", [robogene_bin, "read", "/show", "/pycam"], yarp_env)
    line = reader.wait_for_line(r"\[mat\] \[rgb\] \(3 96 65544 8 4\) \{").string
    assert len(line.split("{")[1].rstrip("}").split()) == 8 * 4 * 3


@pytest.mark.parametrize("args, status, message", [
    ((), 2, "no device given: use --device NAME"),
    (("--device", "no_such_device", "--name", "/x"), 1, "unknown device 'no_such_device' (known devices: "),
    (("--device", "test_motor", "--name", "motors"), 1, "key 'name': 'motors' is not a port name"),
    (("--device", "test_motor", "--name", "/m", "--axes", "0"), 1,
     "device 'test_motor': command line argument 7: key 'axes': 0 is outside [1, 64]"),
    (("--device", "grabberDual", "--name", "/g"), 1, "no 'subdevice' key naming the device to serve"),
    (("--from",), 1, "key 'from': expected a word or a \"string\""),
])
def test_bad_input_is_named(name_server, yarp_env, args, status, message):
    run = run_pydev(yarp_env, "--server", name_server.address, *args)
    assert run.returncode == status, run
    assert message in run.stderr and "Traceback" not in run.stderr, run.stderr


def test_a_bad_ini_file_is_named_with_its_line(name_server, yarp_env, tmp_path):
    ini = tmp_path / "bad.ini"
    ini.write_text("device test_motor\n[group\n")
    run = run_pydev(yarp_env, "--server", name_server.address, "--from", str(ini))
    assert run.returncode == 1 and f"{ini}:2:1: a group header is [name]" in run.stderr, run.stderr
