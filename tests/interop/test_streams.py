# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Streaming between real YARP tools and ours, on a real yarpserver: every committed YARP vector that
fits on one line goes through, and the text printed at the far end must be YARP's own rendering."""
import pytest

from interop_cases import assert_same_lines, by_name, line_cases

pytestmark = pytest.mark.timeout(120)

# A handful that cover every type, for the per-carrier runs.
CARRIER_CASES = ["capture_sniff_yarp_write", "capture_types", "list_mixed", "int64_min", "blob_bytes",
                 "vocab_reply", "float_tenth", "string_nul_escape"]


def test_yarp_write_to_yarp_read_every_vector(yarpserver, yarp, yarp_bottle_vectors):
    """The reference run: proves the vectors are what YARP's own tools print."""
    cases = line_cases(yarp_bottle_vectors)
    reader = yarp.read("/interop/yr")
    writer = yarp.write("/interop/yw", "/interop/yr")
    for case in cases:
        writer.send(case["text"])
    assert_same_lines(cases, reader.wait_data(len(cases), 30), "yarp write -> yarp read")


def test_yarp_write_to_robogene_read(yarpserver, yarp, ours, yarp_bottle_vectors):
    cases = line_cases(yarp_bottle_vectors)
    reader = ours.read("/interop/or")
    writer = yarp.write("/interop/yw", "/interop/or")
    for case in cases:
        writer.send(case["text"])
    got = reader.wait_data(len(cases), 30)
    assert_same_lines(cases, got, "yarp write -> robogene read")


def test_robogene_write_to_yarp_read(yarpserver, yarp, ours, yarp_bottle_vectors):
    cases = line_cases(yarp_bottle_vectors)
    reader = yarp.read("/interop/yr")
    writer = ours.write("/interop/ow", "/interop/yr")
    reader.wait_output(r"Receiving input from /interop/ow to /interop/yr using tcp", 15)
    for case in cases:
        writer.send(case["text"])
    got = reader.wait_data(len(cases), 30)
    assert_same_lines(cases, got, "robogene write -> yarp read")


@pytest.mark.parametrize("carrier", ["tcp", "fast_tcp", "udp", "text", "text_ack"])
def test_yarp_connect_yarp_writer_to_robogene_reader(carrier, yarpserver, yarp, ours, yarp_bottle_vectors):
    cases = by_name(yarp_bottle_vectors, CARRIER_CASES)
    reader = ours.read("/interop/or")
    writer = yarp.write("/interop/yw")
    done = yarp.cmd("connect", "/interop/yw", "/interop/or", carrier)
    assert done.returncode == 0, done
    writer.wait_output(rf"Sending output from /interop/yw to /interop/or using {carrier}", 15)
    for case in cases:
        writer.send(case["text"])
    assert_same_lines(cases, reader.wait_data(len(cases), 15), f"yarp write -{carrier}-> robogene read")


@pytest.mark.parametrize("carrier", ["tcp", "fast_tcp", "udp", "text", "text_ack"])
def test_yarp_connect_robogene_writer_to_yarp_reader(carrier, yarpserver, yarp, ours, yarp_bottle_vectors):
    """`yarp connect` drives our output port through admin over text_ack; our port then dials YARP."""
    cases = by_name(yarp_bottle_vectors, CARRIER_CASES)
    reader = yarp.read("/interop/yr")
    writer = ours.write("/interop/ow")
    done = yarp.cmd("connect", "/interop/ow", "/interop/yr", carrier)
    assert done.returncode == 0, done
    reader.wait_output(rf"Receiving input from /interop/ow to /interop/yr using {carrier}", 15)
    for case in cases:
        writer.send(case["text"])
    assert_same_lines(cases, reader.wait_data(len(cases), 15), f"robogene write -{carrier}-> yarp read")
