# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The runtime's layers are one way (docs/architecture.md), and breaking that is caught twice:
an upward include fails the build of the layer, and the checker names the file and line; an
upward link in CMake is named by the checker too."""
from __future__ import annotations

import json
import shlex
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
import check_layers  # noqa: E402

ROOT = check_layers.ROOT
PLANTED = "runtime/carriers/src/carrier/tcp_carrier.cpp"


def copy_tree(dest: Path) -> Path:
    """The CMake inputs of the C++ build (what the top-level CMakeLists.txt adds), copied."""
    shutil.copy2(ROOT / "CMakeLists.txt", dest / "CMakeLists.txt")
    for part in ("runtime", "drivers", "hardware/electronics/firmware"):
        shutil.copytree(ROOT / part, dest / part, ignore=shutil.ignore_patterns("__pycache__", "corpus"))
    # The firmware's CMake reads the board revision from its one source.
    (dest / "hardware/electronics/generator").mkdir(parents=True)
    shutil.copy2(ROOT / "hardware/electronics/generator/design.py", dest / "hardware/electronics/generator")
    return dest


def plant(file: Path, line: str) -> int:
    """Inserts `line` after the file's last #include; returns its line number."""
    lines = file.read_text().splitlines(keepends=True)
    last = max(i for i, text in enumerate(lines) if text.startswith("#include"))
    lines.insert(last + 1, line + "\n")
    file.write_text("".join(lines))
    return last + 2


def test_the_runtime_is_layered_one_way():
    assert check_layers.check(ROOT) == []


def test_every_layer_sees_only_its_own_and_lower_headers():
    layers = check_layers.read_layers(ROOT)
    check_layers.check_graph(layers, read_targets(ROOT), ROOT)
    seen = {layer.name: set(layer.includes) for layer in layers}
    assert seen["base"] == {"runtime/base/include"}
    assert seen["carriers"] == {"runtime/carriers/include", "runtime/bottle/include", "runtime/base/include"}
    assert "runtime/nameserver/include" not in seen["devices"]
    assert "runtime/devices/include" not in seen["nameserver"]


def read_targets(source: Path) -> dict:
    with tempfile.TemporaryDirectory(prefix="robogene-layers-test-") as build:
        return check_layers.read_targets(check_layers.configure(source, Path(build)))


def test_a_planted_upward_include_is_reported_with_file_and_line(tmp_path):
    tree = copy_tree(tmp_path)
    line = plant(tree / PLANTED, '#include "robogene/port.hpp"')
    problems = check_layers.check(tree)
    assert f"{PLANTED}:{line}: includes robogene/port.hpp of the layer ports, which is not below carriers" \
        in "\n".join(problems), problems
    assert len(problems) == 1, problems


def test_a_relative_include_into_another_folder_is_reported(tmp_path):
    tree = copy_tree(tmp_path)
    fallback = "runtime/nameserver/src/name/fallback.cpp"
    line = plant(tree / fallback, '#include "../../../carriers/src/carrier/binary_framing.hpp"')
    problems = check_layers.check(tree)
    assert len(problems) == 1, problems
    assert problems[0].startswith(f"{fallback}:{line}: includes ../../../carriers/src/carrier/binary_framing.hpp "
                                  "(runtime/carriers/src/carrier/binary_framing.hpp), a private header"), problems


def test_a_planted_upward_include_fails_the_build(tmp_path):
    """The compile command CMake gives the carriers layer, run on the planted file: the compiler
    does not find the ports' header. The same command on the file as committed succeeds."""
    build = tmp_path / "build"
    check_layers.configure(ROOT, build)
    commands = json.loads((build / "compile_commands.json").read_text())
    entry = next(c for c in commands if Path(c["file"]).resolve() == (ROOT / PLANTED).resolve())
    planted = tmp_path / "tcp_carrier.cpp"
    shutil.copy2(ROOT / PLANTED, planted)
    plant(planted, '#include "robogene/port.hpp"')

    def compile_(source: Path) -> subprocess.CompletedProcess:
        args = shlex.split(entry["command"])
        out = args.index("-o")
        args[out + 1] = str(tmp_path / "out.o")
        args[args.index(entry["file"])] = str(source)
        # Private headers beside the original ("binary_framing.hpp") stay reachable.
        args.insert(1, f"-iquote{(ROOT / PLANTED).parent}")
        return subprocess.run(args + ["-fsyntax-only"], cwd=entry["directory"], capture_output=True, text=True)

    assert compile_(ROOT / PLANTED).returncode == 0
    failed = compile_(planted)
    assert failed.returncode != 0
    assert "robogene/port.hpp: No such file or directory" in failed.stderr, failed.stderr


@pytest.mark.parametrize("cmake, complaint", [
    # A cycle: CMake orders the build by dropping one edge, the include path still shows it.
    ("target_link_libraries(robogene_carriers PUBLIC robogene_nameserver)",
     "robogene_carriers compiles with runtime/nameserver/include on its include path, the headers of the "
     "higher layer nameserver"),
    ("target_link_libraries(robogene_bottle PUBLIC robogene_carriers)",
     "robogene_bottle compiles with runtime/carriers/include on its include path"),
    # (Linking robogene_drivers would be a cycle through an OBJECT library, which CMake refuses.)
    ("target_link_libraries(robogene_devices PUBLIC robogene_motor_core)",
     "robogene_devices links robogene_motor_core, which is not a runtime layer"),
    ("add_dependencies(robogene_testing robogene)",
     "robogene_testing depends on the app robogene; nothing may depend on an app"),
])
def test_an_upward_link_is_reported(tmp_path, cmake, complaint):
    tree = copy_tree(tmp_path)
    with (tree / "runtime/CMakeLists.txt").open("a") as f:
        f.write(cmake + "\n")
    problems = check_layers.check(tree, source=tree)
    assert any(complaint in p for p in problems), problems
