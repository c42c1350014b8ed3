# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""YARP to YARP through the harness: proves the peer build, the private network, the process
fixtures and the committed vectors before any of our code is involved."""
import pytest

import interop_net
from interop_cases import by_name

pytestmark = pytest.mark.timeout(90)

STREAM_CASES = ["capture_sniff_yarp_write", "capture_types", "list_mixed", "vocab_reply", "blob_bytes",
                "float_tenth", "int64_min", "string_escaped_quote_backslash"]


def test_yarpserver_answers_queries_for_itself(yarpserver, net):
    root = interop_net.query(net.ns_port, "/root")
    assert (root.host, root.port, root.carrier) == ("127.0.0.1", net.ns_port, "tcp")


def test_yarp_write_to_yarp_read_matches_committed_vectors(yarpserver, yarp, yarp_bottle_vectors):
    cases = by_name(yarp_bottle_vectors, STREAM_CASES)
    reader = yarp.read("/smoke/r")
    writer = yarp.write("/smoke/w", "/smoke/r")
    for case in cases:
        writer.send(case["text"])
    got = reader.wait_data(len(cases), 10)
    assert got == [c["canonical_text"] for c in cases]


def test_yarp_rpc_to_yarp_echo_server(yarpserver, yarp):
    yarp.echo_server("/smoke/echo")
    client = yarp.rpc("/smoke/echo")
    client.send('[set] 1 2.5 "a b"')
    line = client.wait_output(r"^Response: ", 10, "stdout")
    assert line == 'Response: [set] 1 2.5 "a b"'


def test_yarpdev_fake_motors_answer_the_control_board_protocol(yarpserver, yarp):
    yarp.fake_motors("/smoke/motors", joints=4)
    client = yarp.rpc("/smoke/motors/rpc:i")
    client.send("[get] [axes]")
    line = client.wait_output(r"^Response: ", 10, "stdout")
    assert line.startswith("Response: [is] [axes] 4 [tsta] ") and line.endswith(" [ok]"), line
