# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""robogene.BufferedPort: latest-only against strict buffering, the strict bound, read callbacks
(called on the input thread with the GIL, exceptions reported, never deadlocking close), and
prepare()/write()."""
from __future__ import annotations

import sys
import threading
import time

import pytest

import robogene

pytestmark = pytest.mark.timeout(60)


def wait_until(condition, timeout: float = 10.0) -> None:
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline:
            raise AssertionError("condition not met in time")
        time.sleep(0.01)


@pytest.fixture
def writer(network):
    with robogene.Port("/py/bw", network=network) as w:
        yield w


def send_numbers(writer, target: str, n: int) -> None:
    writer.add_output(target)
    for i in range(n):
        assert writer.write([i])


def test_strict_keeps_every_message_in_order(network, writer):
    with robogene.BufferedPort("/py/strict", policy="strict", network=network) as bp:
        send_numbers(writer, "/py/strict", 20)
        wait_until(lambda: bp.pending == 20)
        assert [bp.read(timeout=1)[0].as_int() for _ in range(20)] == list(range(20))
        assert bp.dropped == 0 and bp.read(timeout=0) is None


def test_latest_only_keeps_the_newest(network, writer):
    with robogene.BufferedPort("/py/latest", policy=robogene.BufferPolicy.LATEST_ONLY, network=network) as bp:
        send_numbers(writer, "/py/latest", 20)
        wait_until(lambda: bp.dropped == 19)
        assert bp.pending == 1
        assert bp.read(timeout=1).to_text() == "19"
        assert bp.read(timeout=0) is None


def test_strict_capacity_drops_the_oldest(network, writer):
    with robogene.BufferedPort("/py/bounded", policy="strict", capacity=5, network=network) as bp:
        send_numbers(writer, "/py/bounded", 8)
        wait_until(lambda: bp.dropped == 3)
        assert [bp.read(timeout=1)[0].as_int() for _ in range(5)] == [3, 4, 5, 6, 7]


def test_bad_policy_and_capacity(network):
    with pytest.raises(ValueError, match='unknown buffer policy "newest"'):
        robogene.BufferedPort(policy="newest")
    with pytest.raises(ValueError, match="capacity"):
        robogene.BufferedPort(policy="strict", capacity=0)


def test_callback_runs_on_the_input_thread(network, writer):
    with robogene.BufferedPort("/py/cb", policy="strict", network=network) as bp:
        seen = []
        main = threading.get_ident()
        bp.on_read(lambda b, info: seen.append((b[0].as_int(), info.sender, threading.get_ident() != main)))
        send_numbers(writer, "/py/cb", 10)
        wait_until(lambda: len(seen) == 10)
        assert seen == [(i, "/py/bw", True) for i in range(10)]
        assert bp.pending == 0, "a callback takes the messages instead of the buffer"
        bp.on_read(None)
        writer.write(["buffered"])
        assert bp.read(timeout=10).to_text() == "buffered"


def test_callback_exception_goes_to_unraisablehook(network, writer, monkeypatch):
    reported = []
    monkeypatch.setattr(sys, "unraisablehook", lambda u: reported.append(u))
    with robogene.BufferedPort("/py/raise", network=network) as bp:
        after = []

        def callback(b, info):
            if b[0].as_int() == 0:
                raise ValueError("bad sample")
            after.append(b[0].as_int())
        bp.on_read(callback)
        send_numbers(writer, "/py/raise", 2)
        wait_until(lambda: after == [1])
    assert len(reported) == 1 and isinstance(reported[0].exc_value, ValueError)
    assert reported[0].object == "robogene.BufferedPort read callback"


def test_close_while_a_callback_runs_does_not_deadlock(network, writer):
    bp = robogene.BufferedPort("/py/slow", network=network)
    entered, finished = threading.Event(), []

    def slow(b, info):
        entered.set()
        time.sleep(0.5)  # holds the GIL on and off while close() waits for this thread
        finished.append(b.to_text())
    bp.on_read(slow)
    writer.add_output("/py/slow")
    threading.Thread(target=lambda: writer.write(["x"]), daemon=True).start()
    assert entered.wait(10)
    bp.close()  # joins the input thread: must release the GIL the callback needs
    assert finished == ["x"]
    assert network.query("/py/slow") is None


def test_close_from_its_own_callback_is_refused(network, writer):
    with robogene.BufferedPort("/py/self", network=network) as bp:
        errors = []

        def callback(b, info):
            try:
                bp.close()
            except ValueError as e:
                errors.append(str(e))
        bp.on_read(callback)
        send_numbers(writer, "/py/self", 1)
        wait_until(lambda: errors)
        assert "from its own callback" in errors[0]
        assert bp.is_open


def test_a_closed_buffered_port_cannot_reopen(network):
    bp = robogene.BufferedPort("/py/once", network=network)
    bp.close()
    with pytest.raises(ValueError, match="cannot be opened again"):
        bp.open("/py/once", network=network)


def test_prepare_and_write(network):
    with robogene.BufferedPort("/py/sink", policy="strict", network=network) as sink, \
            robogene.BufferedPort("/py/source", network=network) as source:
        source.add_output("/py/sink")
        b = source.prepare()
        b.add("hello").add(3)
        assert source.write()
        assert source.write(["explicit"])
        assert sink.read(timeout=10).to_text() == "hello 3"
        got, info = sink.read_with_info(timeout=10)
        assert got.to_text() == "explicit" and info.sender == "/py/source"
        assert source.prepare().to_text() == "", "prepare() clears"


def test_close_ends_a_blocking_read(network):
    bp = robogene.BufferedPort("/py/wait", network=network)
    result = []
    t = threading.Thread(target=lambda: result.append(bp.read()))
    t.start()
    time.sleep(0.3)
    bp.close()
    t.join(5)
    assert result == [None]
