# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""C++ <-> Python on many values: what one language encodes the other decodes to the same text, and
any frame at all (random identifiers and bytes) gets the same answer, or the same error, from both."""
import random

import pytest

# The first test of the module builds the C++ side (g++), which can take minutes on a busy machine.
pytestmark = pytest.mark.timeout(900)


def _edge_values(f, rng):
    bits = 8 * f.size
    lo, hi = (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if f.signed else (0, (1 << bits) - 1)
    return [lo, hi, 0, 1, -1 if f.signed else 2, rng.randint(lo, hi), rng.randint(lo, hi)]


def _envelopes(can, rng):
    for name, cls in sorted(can.MESSAGES.items()):
        for i in range(7):
            values = {}
            for f in cls.FIELDS:
                if f.kind == "enum":
                    values[f.name] = rng.choice(list(f.type))
                elif f.kind == "flags":
                    values[f.name] = f.type(rng.getrandbits(8 * f.size))
                elif f.kind == "bool":
                    values[f.name] = bool(rng.getrandbits(1))
                else:
                    raw = _edge_values(f, rng)[i]
                    values[f.name] = raw * f.scale + f.offset if f.kind == "real" else raw
            board = rng.randint(1, 14)
            m = cls(**values)
            if cls.KIND == "request":
                yield can.command(board, rng.randint(0, 1), m)
            elif cls.KIND == "reply":
                yield can.reply(board, rng.randint(0, 1), m)
            else:
                yield can.broadcast(board, m)


def test_python_frames_decode_in_cpp_and_back(can, cpp):
    rng = random.Random(20261122)
    count = 0
    for env in _envelopes(can, rng):
        frame = str(can.encode(env))
        text = can.to_text(env)
        assert cpp.decode(frame) == ("ok", text), text
        assert cpp.encode(text) == ("ok", frame), text
        assert can.decode(can.Frame(int(frame[:3], 16), bytes.fromhex(frame[4:]))) == env
        count += 1
    assert count == 7 * len(can.MESSAGES)


def test_scaled_values_round_half_away_from_zero_alike(can, cpp):
    for speed in (5.0, -5.0, 15.0, -15.0, 4.999999, 327674.99, -327684.99):
        text = f"position_move src=0 dst=1 axis=0 position=0 speed={speed!r}"
        try:
            frame = str(can.encode(can.from_text(text)))
        except can.CodecError as exc:
            assert cpp.encode(text) == ("error", str(exc))
            continue
        assert cpp.encode(text) == ("ok", frame)
    assert str(can.encode(can.from_text("position_move src=0 dst=1 axis=0 position=0 speed=5")))[-4:] == "0100"
    assert str(can.encode(can.from_text("position_move src=0 dst=1 axis=0 position=0 speed=-5")))[-4:] == "FFFF"


@pytest.mark.parametrize("seed", range(4))
def test_random_frames_get_the_same_answer(can, cpp, seed):
    rng = random.Random(seed)
    ids = [0x000 | rng.randint(0, 0x0FF) for _ in range(150)] + [0x100 | rng.randint(0, 0xFF) for _ in range(100)] + \
        [rng.randint(0, 0x7FF) for _ in range(50)]
    for can_id in ids:
        n = rng.choice([0, 1, 2, 3, 5, 7, 8, 8, 8])
        data = bytes(rng.getrandbits(8) for _ in range(n))
        if n and can_id < 0x100 and rng.random() < 0.7:  # mostly known commands, so decoding gets far
            data = bytes([rng.choice(list(can.Command)) | rng.choice([0, 0x80])]) + data[1:]
        frame = can.Frame(can_id, data)
        try:
            expected = ("ok", can.to_text(can.decode(frame)))
        except can.CodecError as exc:
            expected = ("error", str(exc))
        assert cpp.decode(str(frame)) == expected, str(frame)
