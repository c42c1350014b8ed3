# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Values only YARP's typed API makes (int8, int16, float32, homogeneous lists of them, a string
with a NUL) sent by a real YARP port to `robogene read`: printed as YARP prints them."""
import json

import pytest

from interop_peer import ROOT

pytestmark = pytest.mark.timeout(90)


@pytest.mark.parametrize("carrier", ["tcp", "udp", "text"])
def test_typed_yarp_values_reach_robogene_read(carrier, yarpserver, yarp, ours):
    vectors = json.loads((ROOT / "tests" / "vectors" / "yarp3_typed_values.json").read_text())
    mine = ours.read("/interop/or")
    writer = yarp.python("typed writer", "yarp_typed_writer.py", "/interop/tw")
    writer.wait_output(r"^ready$", 15)
    assert yarp.cmd("connect", "/interop/tw", "/interop/or", carrier).returncode == 0
    writer.wait_output(rf"Sending output from /interop/tw to /interop/or using {carrier}", 15)
    writer.send("go")
    got = mine.wait_data(len(vectors), 15)
    assert got == [v["canonical_text"] for v in vectors]
