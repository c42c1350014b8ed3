# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""python -m robogene.can.candump decodes a candump log with our protocol and reports bad lines."""
import io
from pathlib import Path

import pytest

SESSION = Path(__file__).resolve().parent / "data" / "head-session.log"


@pytest.fixture(scope="module")
def candump(can):
    from robogene.can import candump as module
    return module


def test_decodes_the_recorded_session(can, candump):
    out, err = io.StringIO(), io.StringIO()
    with SESSION.open() as log:
        assert candump.decode_log(log, out, err, "session") == 0
    assert err.getvalue() == ""
    lines = out.getvalue().splitlines()
    assert len(lines) == len(SESSION.read_text().splitlines())
    assert lines[0] == "(1795392000.001000) can0 001#5B0100  get_firmware_version src=0 dst=1 axis=0 " \
                       "protocol_major=1 protocol_minor=0"
    for line in lines:  # every text form reads back to the frame it came from
        frame, text = line.split("  ", 1)
        assert str(can.encode(can.from_text(text))) == frame.split()[-1]


def test_reports_bad_lines_with_their_number(candump):
    log = io.StringIO("001#1BE80300001900\n\nhello\n001#1B00\n(now) can0 131#640000009CFFFFFF\n001#123\n")
    out, err = io.StringIO(), io.StringIO()
    assert candump.decode_log(log, out, err, "x.log") == 1
    assert err.getvalue().splitlines() == [
        "x.log:3: not a candump frame of an 11-bit identifier: 'hello'",
        "x.log:4: 001#1B00: position_move has 7 data bytes, this frame 2",
        "x.log:5: not a candump frame of an 11-bit identifier: '(now) can0 131#640000009CFFFFFF'",
        "x.log:6: data '123' is not 0 to 8 bytes of hex"]
    assert out.getvalue().splitlines() == ["001#1BE80300001900  position_move src=0 dst=1 axis=0 position=1000 speed=250"]


def test_read_log_names_the_line(candump):
    entries = list(candump.read_log(["(2.000001) vcan0 123#0801000000000000\n", "\n"]))
    assert entries[0][0] == 1 and entries[0][1].timestamp == 2.000001 and entries[0][1].interface == "vcan0"
    with pytest.raises(ValueError, match="line 2: not a candump frame"):
        list(candump.read_log(["001#2E", "001 2E"]))


def test_cli_reads_a_file_and_fails_on_a_missing_one(candump, capsys, tmp_path):
    log = tmp_path / "one.log"
    log.write_text("003#4905000000\n")
    assert candump.main([str(log)]) == 0
    assert capsys.readouterr().out == "003#4905000000  set_broadcast_policy src=0 dst=3 axis=0 mask=0x00000005\n"
    assert candump.main([str(tmp_path / "none.log")]) == 2
    assert "none.log: cannot read: No such file or directory" in capsys.readouterr().err
