# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Fixtures of the CAN protocol and board-config tests: the generated Python codec from this source
tree, the generated C++ codec compiled into a line-driven tool, and the runtime's ini reader."""
import os
import shutil
import subprocess
import sys
import types
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
# Every runtime layer's public headers (runtime/layers.cmake).
RUNTIME_INCLUDES = sorted((ROOT / "runtime").glob("*/include"))
HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(ROOT / "codegen"))

# robogene.can is pure Python; the compiled core is not needed, so a bare package stands in for it
# when robogene is not installed.
_SOURCE = str(ROOT / "runtime" / "python" / "robogene")
try:
    import robogene
except ImportError:
    robogene = types.ModuleType("robogene")
    robogene.__path__ = []
    sys.modules["robogene"] = robogene
if _SOURCE not in robogene.__path__:
    robogene.__path__.insert(0, _SOURCE)

CXX = os.environ.get("CXX", "g++")
CC = os.environ.get("CC", "gcc")


def compile_cxx(sources, out: Path, includes, warnings_are_errors: bool = True) -> Path:
    strict = ["-Wall", "-Wextra", "-Wpedantic", "-Werror"] if warnings_are_errors else []
    cmd = [CXX, "-std=c++17", "-O0", *strict, *[f"-I{i}" for i in includes],
           *map(str, sources), "-o", str(out)]
    result = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, f"{' '.join(cmd)}\n{result.stderr}"
    return out


@pytest.fixture(scope="session")
def can():
    from robogene import can as module
    return module


@pytest.fixture(scope="session")
def build_dir(tmp_path_factory):
    if shutil.which(CXX) is None:
        pytest.fail(f"{CXX} is needed to build the C++ side of these tests")
    return tmp_path_factory.mktemp("can-build")


class CodecTool:
    """The C++ codec behind a pipe: one request line in, one answer line out."""

    def __init__(self, path: Path):
        self.proc = subprocess.Popen([str(path)], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)

    def ask(self, line: str) -> tuple[str, str]:
        self.proc.stdin.write(line + "\n")
        self.proc.stdin.flush()
        answer = self.proc.stdout.readline().rstrip("\n")
        assert answer, f"the C++ codec tool gave no answer to {line!r}"
        status, _, rest = answer.partition(" ")
        return status, rest

    def encode(self, text: str) -> tuple[str, str]:
        return self.ask("encode " + text)

    def decode(self, frame: str) -> tuple[str, str]:
        return self.ask("decode " + frame)

    def close(self) -> None:
        self.proc.stdin.close()
        self.proc.wait(timeout=30)


@pytest.fixture(scope="session")
def cpp(build_dir):
    gen = ROOT / "drivers" / "can" / "generated"
    exe = compile_cxx([HERE / "codec_tool.cpp", gen / "motor_control.cpp"], build_dir / "codec_tool",
                      [gen, ROOT / "drivers" / "can" / "include", *RUNTIME_INCLUDES])
    tool = CodecTool(exe)
    yield tool
    tool.close()


@pytest.fixture(scope="session")
def property_tool(build_dir):
    """The runtime's Property ini reader (runtime/devices/src/dev/property*.cpp) in a small program."""
    src = ROOT / "runtime" / "devices" / "src"
    bottle = ROOT / "runtime" / "bottle" / "src"
    sources = [HERE / "property_tool.cpp", *sorted(bottle.glob("*.cpp")),
               src / "dev" / "property.cpp", src / "dev" / "property_sources.cpp", src / "dev" / "searchable.cpp"]
    # The runtime's warnings are the runtime build's business; here only the reading is tested.
    return compile_cxx(sources, build_dir / "property_tool", [*RUNTIME_INCLUDES, bottle],
                       warnings_are_errors=False)
