# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Buffers and strings the binding did not expect (issue 11): reversed and strided views are read
item by item, never past their ends; text that is not UTF-8 (any bytes a peer sends) decodes
without raising and encodes back to the same bytes; every vocab code survives the text form.
The property tests (Hypothesis) round-trip bytes and text through both wire forms."""
from __future__ import annotations

import array
import socket
import threading

from hypothesis import given, settings
from hypothesis import strategies as st

import robogene

NOT_UTF8 = b"caf\xe9 \xff\xfe end"


def without_terminator(raw: bytes) -> bytes:
    return raw[:-1] if raw.endswith(b"\0") else raw


def test_reversed_and_strided_views_are_read_as_seen():
    data = bytes(range(32))
    # Before: the pointer of a reversed view (its last byte) was read forwards, 32 bytes past it.
    assert robogene.Value.blob(memoryview(data)[::-1]).as_bytes() == data[::-1]
    assert robogene.Value.blob(memoryview(data)[::3]).as_bytes() == data[::3]
    assert robogene.Value.blob(memoryview(data)[5:9]).as_bytes() == data[5:9]
    b = robogene.Bottle()
    b.add(memoryview(bytearray(data))[::-2])
    assert b[0].as_bytes() == data[::-2]
    # A strided view of wider items: its bytes, item after item.
    words = array.array("H", [0x0102, 0x0304, 0x0506, 0x0708])
    assert robogene.Value.blob(memoryview(words)[::-1]).as_bytes() == b"".join(
        w.to_bytes(2, "little") for w in reversed(words))
    wire = robogene.Bottle.from_text('1 "two" (3)').to_bytes()
    assert robogene.Bottle.from_bytes(memoryview(wire[::-1])[::-1]).to_text() == "1 two (3)"


def test_text_that_is_not_utf8_never_raises_and_round_trips():
    s = NOT_UTF8.decode("utf-8", "surrogateescape")
    wire = robogene.Bottle([s, 1]).to_bytes()
    assert NOT_UTF8 in wire  # the peer's bytes, as they were
    b = robogene.Bottle.from_bytes(wire)  # what a port hands its reader
    # Before: each of these raised UnicodeDecodeError.
    text, shown, represented = b.to_text(), str(b), repr(b)
    assert "\\udce9" in represented and text == shown
    assert b[0].as_string().encode("utf-8", "surrogateescape") == NOT_UTF8
    assert b.to_python()[0].encode("utf-8", "surrogateescape") == NOT_UTF8
    assert str(b[0]) == b[0].to_text() and "Value(string" in repr(b[0])
    assert robogene.Bottle.from_text(text).to_bytes() == wire


def test_a_sender_name_that_is_not_utf8_reaches_a_python_reader():
    with robogene.Port("/py/hostile", at=("127.0.0.1", 0)) as r:
        got = []
        t = threading.Thread(target=lambda: got.append(r.read_with_info(timeout=10)))
        t.start()
        with socket.create_connection((r.contact.host, r.contact.port), timeout=5) as s:
            s.sendall(b"CONNACK /w\xff\r\n")
            s.recv(100)  # "Welcome ..."
            s.sendall(b'd\r\n"caf\xe9"\r\n')
            t.join(10)
        bottle, info = got[0]
        assert info.sender.encode("utf-8", "surrogateescape") == b"/w\xff"
        assert "MessageInfo(sender='/w\\udcff'" in repr(info)
        assert bottle[0].as_string().encode("utf-8", "surrogateescape") == b"caf\xe9"


def test_a_vocab_holding_nul_round_trips_through_text():
    v = robogene.Value.vocab(0x00620061)  # 'a', NUL, 'b'
    b = robogene.Bottle([v])
    assert b.to_text() == "[a\\0b]"
    assert robogene.Bottle.from_text(b.to_text())[0].as_vocab() == 0x00620061


@settings(max_examples=300, deadline=None)
@given(st.binary(max_size=200), st.integers(min_value=-4, max_value=4).filter(bool), st.integers(0, 8))
def test_property_any_view_of_any_bytes_is_copied_as_seen(data, step, start):
    view = memoryview(data)[start::step]
    assert robogene.Value.blob(view).as_bytes() == bytes(view)
    b = robogene.Bottle([view])
    assert robogene.Bottle.from_bytes(b.to_bytes())[0].as_bytes() == bytes(view)
    assert robogene.Bottle.from_text(b.to_text())[0].as_bytes() == bytes(view)


@settings(max_examples=300, deadline=None)
@given(st.binary(max_size=100))
def test_property_any_bytes_as_a_string_round_trip_binary_and_text(raw):
    s = raw.decode("utf-8", "surrogateescape")
    b = robogene.Bottle([s])
    back = robogene.Bottle.from_text(b.to_text())
    assert back[0].as_string().encode("utf-8", "surrogateescape") == raw
    assert back.to_bytes() == b.to_bytes()
    # The binary reader drops one trailing NUL (old peers counted a terminator; docs/protocol/bottle.md).
    back = robogene.Bottle.from_bytes(b.to_bytes())
    assert back[0].as_string().encode("utf-8", "surrogateescape") == without_terminator(raw)
    assert repr(b) and str(b) == b.to_text()


@settings(max_examples=300, deadline=None)
@given(st.text(max_size=60))
def test_property_any_text_round_trips(text):
    b = robogene.Bottle([text, [text]])
    assert robogene.Bottle.from_text(b.to_text()).to_python() == [text, [text]]
    wire = without_terminator(text.encode()).decode()
    assert robogene.Bottle.from_bytes(b.to_bytes()).to_python() == [wire, [wire]]


@settings(max_examples=500, deadline=None)
@given(st.integers(min_value=-(2**31), max_value=2**31 - 1))
def test_property_every_vocab_code_round_trips_through_text(code):
    b = robogene.Bottle([robogene.Value.vocab(code)])
    back = robogene.Bottle.from_text(b.to_text())
    assert back[0].is_vocab() and back[0].as_vocab() == code, b.to_text()


@settings(max_examples=500, deadline=None)
@given(st.binary(max_size=300))
def test_property_any_bytes_from_the_network_decode_or_fail_cleanly(wire):
    try:
        b = robogene.Bottle.from_bytes(wire)
    except robogene.ParseError as e:
        assert e.position >= 0 and str(e)
        return
    text = b.to_text()
    assert repr(b) and str(b) == text
    again = robogene.Bottle.from_bytes(b.to_bytes())
    assert len(again) == len(b)
