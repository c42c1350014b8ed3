# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The Pythonic side of Bottle and Value: conversions, errors, and zero-copy blobs."""
import pytest

import robogene


def test_python_values_convert_like_the_text_form():
    b = robogene.Bottle(["action", "go left", [10, 20, 30], 2.5, 2**40, b"\x00\xff"])
    assert b.to_text() == 'action "go left" (10 20 30) 2.5 1099511627776 {0 255}'
    assert [v.type for v in b] == ["string", "string", "list", "float64", "int64", "blob"]
    assert b == robogene.Bottle.from_text(b.to_text())


def test_paper_table_round_trips_through_bytes():
    for text in ["10 20 30", "10.0 20.5 31.4159", 'action "go left" (10 20 30)', "[set] [pos] 1 30.3"]:
        b = robogene.Bottle.from_text(text)
        assert robogene.Bottle.from_bytes(b.to_bytes()) == b


def test_vocab_codes_match_yarp_packing():
    assert robogene.vocab("set") == 0x00746573
    assert robogene.vocab_to_string(robogene.vocab("axes")) == "axes"
    assert robogene.Value.vocab("toolong").as_vocab_text() == "tool"
    # YARP lets a string stand for a vocab (`get axes` typed at `yarp rpc`).
    assert robogene.Value.string("get").as_vocab() == robogene.vocab("get")


def test_blob_buffer_is_shared_not_copied():
    v = robogene.Value.blob(bytes(640 * 480 * 3))
    view = memoryview(v)
    assert view.nbytes == 921600 and view.format == "B"
    view[0] = 0x41
    assert v.as_bytes()[:1] == b"A"


def test_non_blob_has_no_buffer():
    with pytest.raises(BufferError):
        memoryview(robogene.Value.int32(3))


def test_type_errors_are_clear():
    with pytest.raises(robogene.Error, match="string"):
        robogene.Value.string("x").as_int()
    with pytest.raises(TypeError, match="cannot put a dict"):
        robogene.Bottle([{"a": 1}])
    with pytest.raises(IndexError, match="out of range"):
        robogene.Bottle([1])[3]


def test_searchable_lookups():
    b = robogene.Bottle.from_text("(device test_motor) (axes 2) name /motors")
    assert b.find("axes").as_int() == 2
    assert b.find("name").as_string() == "/motors"
    assert b.find("missing").is_null()
    assert b.find_group("device").to_text() == "device test_motor"
