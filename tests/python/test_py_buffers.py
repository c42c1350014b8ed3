# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Float vectors and blobs through the buffer protocol: Bottle.from_floats / add_floats /
to_floats / floats_into with memoryview and array.array (no Python list in between), blob Values
shared in place, and the errors for buffers of the wrong kind."""
from __future__ import annotations

import array
import struct
import threading

import pytest

import robogene


def test_from_floats_float64_and_float32():
    b = robogene.Bottle.from_floats(array.array("d", [1.0, -2.5, 1e300]))
    assert [v.type for v in b] == ["float64"] * 3 and b.to_python() == [1.0, -2.5, 1e300]
    f = robogene.Bottle.from_floats(memoryview(struct.pack("<2f", 0.5, 3.0)).cast("f"))
    assert [v.type for v in f] == ["float32"] * 2 and f.to_python() == [0.5, 3.0]
    # the bytes are YARP's homogeneous float64 list
    assert b.to_bytes() == robogene.Bottle.from_text("1.0 -2.5 1e300").to_bytes()


def test_strided_and_two_dimensional_buffers():
    every_other = memoryview(array.array("d", range(10)))[::2]
    assert robogene.Bottle.from_floats(every_other).to_python() == [0.0, 2.0, 4.0, 6.0, 8.0]
    matrix = memoryview(array.array("d", range(6))).cast("B").cast("d", (2, 3))
    assert robogene.Bottle.from_floats(matrix).to_python() == [0.0, 1.0, 2.0, 3.0, 4.0, 5.0]


def test_add_floats_into_a_nested_list():
    b = robogene.Bottle()
    b.add("pos")
    b.add_list().add_floats(array.array("d", [1.5, 2.5]))
    assert b.to_text() == "pos (1.5 2.5)"


def test_to_floats_is_a_float64_memoryview():
    b = robogene.Bottle.from_text("1 2.5 -3")
    out = b.to_floats()
    assert isinstance(out, memoryview) and out.format == "d" and out.tolist() == [1.0, 2.5, -3.0]
    assert robogene.Bottle().to_floats().tolist() == []


def test_floats_into_fills_a_caller_buffer():
    target = array.array("d", [0.0] * 4)
    assert robogene.Bottle.from_text("0.25 0.5 1").floats_into(target) == 3
    assert target.tolist() == [0.25, 0.5, 1.0, 0.0]
    with pytest.raises(ValueError, match="holds 1 items, the Bottle has 3"):
        robogene.Bottle.from_text("1 2 3").floats_into(array.array("d", [0.0]))
    with pytest.raises(TypeError, match="float64"):
        robogene.Bottle.from_text("1").floats_into(array.array("i", [0]))
    with pytest.raises(BufferError):
        robogene.Bottle.from_text("1").floats_into(bytes(8))


def test_wrong_buffers_and_items_are_named():
    with pytest.raises(TypeError, match="format 'i'"):
        robogene.Bottle.from_floats(array.array("i", [1, 2]))
    with pytest.raises(TypeError, match="Bottle item 1 is a string, not a number: x"):
        robogene.Bottle.from_text('1 "x"').to_floats()


def test_blob_values_share_memory_in_place():
    v = robogene.Value.blob(b"\x01\x02\x03")
    view = memoryview(v)
    assert view.tobytes() == b"\x01\x02\x03" and view.readonly is False
    view[0] = 9
    assert v.as_bytes() == b"\x09\x02\x03", "the memoryview is the Value's own storage"
    with pytest.raises(BufferError):
        memoryview(robogene.Value.int32(1))


def test_float_vector_over_a_port(network):
    samples = array.array("d", [i / 7 for i in range(1000)])
    with robogene.BufferedPort("/py/vec:i", policy="strict", network=network) as r, \
            robogene.Port("/py/vec:o", network=network) as w:
        w.add_output("/py/vec:i")
        threading.Thread(target=lambda: w.write(robogene.Bottle.from_floats(samples))).start()
        got = r.read(timeout=10)
        out = array.array("d", [0.0] * len(got))
        got.floats_into(out)
        assert out == samples
