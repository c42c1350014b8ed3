# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""A command added to the protocol file reaches the C++ and Python codecs, the DBC and the docs after
`generate`, and `check` names every stale file before it."""
import importlib.util
import shutil
import subprocess
import sys

import pytest

from conftest import CXX, ROOT, RUNTIME_INCLUDES
from robogene_codegen.__main__ import main
from robogene_codegen.manifest import MANIFEST, read

# The first test of the module builds the C++ side (g++), which can take minutes on a busy machine.
pytestmark = pytest.mark.timeout(900)

NEW_COMMAND = """      - name: get_supply_voltage
        code: 120
        doc: Read the motor supply voltage.
        reply:
          - {name: voltage, type: uint16, unit: V, scale: 0.001}
"""


@pytest.fixture
def tree(tmp_path):
    root = tmp_path / "tree"
    shutil.copytree(ROOT / "interfaces", root / "interfaces")
    manifest = read(ROOT)
    for rel in [MANIFEST, "hardware/head-parameters.yaml", *manifest.block_documents]:
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(ROOT / rel, root / rel)
    for d in manifest.generated_folders:
        shutil.copytree(ROOT / d, root / d, ignore=shutil.ignore_patterns("__pycache__"), dirs_exist_ok=True)
    shutil.copytree(ROOT / "runtime/python/robogene/can", root / "runtime/python/robogene/can", dirs_exist_ok=True,
                    ignore=shutil.ignore_patterns("__pycache__"))
    return root


def test_added_command_reaches_every_output(tree, capsys, tmp_path):
    proto = tree / "interfaces" / "idl" / "can_motor_control.yaml"
    text = proto.read_text()
    anchor = "      - name: get_firmware_version\n"
    proto.write_text(text.replace(anchor, NEW_COMMAND + anchor))

    assert main(["check", "--root", str(tree), "--only", "idl"]) == 1
    err = capsys.readouterr().err
    for stale in ("drivers/can/generated/motor_control.hpp", "drivers/can/generated/motor_control.cpp",
                  "runtime/python/robogene/can/generated/motor_control.py", "drivers/can/generated/head.dbc",
                  "hardware/electronics/firmware/generated/robogene_can_motor_control.h",
                  "docs/generated/can/motor_control.md",
                  "drivers/can/generated/head.ini"):  # the ini carries the protocol's fingerprint
        assert f"stale: {stale}: differs" in err, err

    assert main(["generate", "--root", str(tree), "--only", "idl"]) == 0
    assert main(["check", "--root", str(tree), "--only", "idl"]) == 0
    capsys.readouterr()

    # Python: the new message encodes and decodes.
    path = tree / "runtime/python/robogene/can/generated/motor_control.py"
    spec = importlib.util.spec_from_file_location("regenerated_motor_control", path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod
    spec.loader.exec_module(mod)
    env = mod.reply(2, 1, mod.GetSupplyVoltageReply(voltage=12.5))
    frame = mod.encode(env)
    assert str(frame) == "020#F8D430"
    assert mod.decode(frame) == env

    # C++: the regenerated codec compiles and has the new struct.
    gen = tree / "drivers" / "can" / "generated"
    probe = tmp_path / "probe.cpp"
    probe.write_text('#include "motor_control.hpp"\n'
                     "static_assert(robogene::can::GetSupplyVoltage::code == 120, \"code\");\n"
                     "static_assert(robogene::can::GetSupplyVoltageReply::length == 3, \"length\");\n")
    for src in (probe, gen / "motor_control.cpp"):
        result = subprocess.run([CXX, "-std=c++17", "-fsyntax-only", "-Wall", "-Wextra", "-Werror", f"-I{gen}",
                                 f"-I{ROOT / 'drivers/can/include'}", *(f"-I{p}" for p in RUNTIME_INCLUDES), str(src)],
                                capture_output=True, text=True, timeout=300)
        assert result.returncode == 0, result.stderr

    # The DBC and the docs know it too.
    assert '120 "get_supply_voltage_reply"' in (gen / "head.dbc").read_text()
    assert "`get_supply_voltage`" in (tree / "docs/generated/can/motor_control.md").read_text()
