# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Every frame of the shared vectors encodes and decodes identically in C++ and Python, and the
malformed ones fail in both with the same message."""
import json
from pathlib import Path

import pytest

# The first test of the module builds the C++ side (g++), which can take minutes on a busy machine.
pytestmark = pytest.mark.timeout(900)

DATA = json.loads((Path(__file__).resolve().parent / "vectors.json").read_text())
FRAMES = DATA["frames"]
IDS = [v["text"].split()[0] + "-" + v["origin"] for v in FRAMES]


def _frame(can, text: str):
    can_id, _, data = text.partition("#")
    return can.Frame(int(can_id, 16), bytes.fromhex(data))


def test_vectors_cover_every_message(can):
    named = {v["text"].split()[0] for v in FRAMES}
    assert named == set(can.MESSAGES)
    assert sum(v["origin"] == "reference" for v in FRAMES) >= 10


@pytest.mark.parametrize("vector", FRAMES, ids=IDS)
def test_python_encodes_and_decodes(can, vector):
    env = can.from_text(vector["text"])
    assert str(can.encode(env)) == vector["frame"]
    decoded = can.decode(_frame(can, vector["frame"]))
    assert decoded == env
    assert can.to_text(decoded) == vector["text"]


@pytest.mark.parametrize("vector", FRAMES, ids=IDS)
def test_cpp_encodes_and_decodes(cpp, vector):
    assert cpp.encode(vector["text"]) == ("ok", vector["frame"])
    assert cpp.decode(vector["frame"]) == ("ok", vector["text"])


@pytest.mark.parametrize("vector", DATA["malformed"], ids=[v["frame"] for v in DATA["malformed"]])
def test_malformed_frames_fail_alike(can, cpp, vector):
    with pytest.raises(can.CodecError) as info:
        can.decode(_frame(can, vector["frame"]))
    assert vector["error"] in str(info.value)
    assert cpp.decode(vector["frame"]) == ("error", str(info.value))


@pytest.mark.parametrize("vector", DATA["bad_text"], ids=[v["error"][:40] for v in DATA["bad_text"]])
def test_bad_text_and_values_fail_alike(can, cpp, vector):
    with pytest.raises(can.CodecError) as info:
        can.encode(can.from_text(vector["text"]))
    assert vector["error"] in str(info.value)
    assert cpp.encode(vector["text"]) == ("error", str(info.value))


def test_python_refuses_wrong_types(can):
    with pytest.raises(can.CodecError, match="position_move.position: 1.5 is not an integer"):
        can.encode(can.command(1, 0, can.PositionMove(position=1.5, speed=0.0)))
    with pytest.raises(can.CodecError, match="set_control_mode.mode: 77 is not a ControlMode"):
        can.encode(can.command(1, 0, can.SetControlMode(mode=77)))
    with pytest.raises(can.CodecError, match="is not a message of the motor_control protocol"):
        can.encode(can.Envelope(0, 1, 0, "position_move"))
    with pytest.raises(can.CodecError, match="data length 9 is more than 8"):
        can.decode(can.Frame(0x001, bytes(9)))
