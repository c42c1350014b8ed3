# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""cantools loads the generated DBC and decodes a recorded candump session to the same values as
our own decoder."""
from pathlib import Path

import pytest

import cantools  # pinned in tools/setup/requirements-can.txt
from cantools.logreader import Parser

ROOT = Path(__file__).resolve().parents[2]
DBC = ROOT / "drivers" / "can" / "generated" / "head.dbc"
DATA = Path(__file__).resolve().parent / "data"
# head-session.log: written by our encoder (tests/can/record_session.py).
# sim-session.log: the bus as `robogene can-sim` (the board simulator) logged it while the
# robogene_can driver (`robogene dev --device robogene_can`) brought the boards up and
# `robogene rpc` moved joints 0, 2, 4, 5 and ran joint 3 in velocity mode; the position, current
# and velocity broadcasts and the driver's control-mode polls are thinned to one in 20 per
# identifier to keep the file small, every other frame is as recorded.
SESSIONS = {"encoder": DATA / "head-session.log", "simulator": DATA / "sim-session.log"}


@pytest.fixture(scope="module")
def db():
    return cantools.database.load_file(str(DBC))  # strict: overlapping or oversized signals fail here


def _expected(can, env) -> dict:
    """Our decoder's values under the DBC's signal names (enums and flags as numbers)."""
    m = env.message
    values = {f.name: getattr(m, f.name) for f in m.FIELDS}
    values = {k: (int(v) if not isinstance(v, float) else v) for k, v in values.items()}
    if m.KIND == "broadcast":
        return values
    return {"command": m.CODE, "axis": env.axis, **{f"{m.NAME}_{k}": v for k, v in values.items()}}


def test_dbc_describes_the_head_bus(db):
    names = {m.name for m in db.messages}
    for board in ("NECK_PITCH_ROLL", "NECK_YAW_EYES_TILT", "EYES_PAN"):
        assert {f"HOST_TO_{board}", f"{board}_REPLY", f"{board}_POSITION", f"{board}_STATUS"} <= names
    assert db.get_message_by_name("HOST_TO_EYES_PAN").frame_id == 0x003
    assert db.get_message_by_name("EYES_PAN_REPLY").frame_id == 0x030
    assert db.get_message_by_name("NECK_PITCH_ROLL_POSITION").frame_id == 0x111
    speed = db.get_message_by_name("HOST_TO_EYES_PAN").get_signal_by_name("position_move_speed")
    assert (speed.scale, speed.unit, speed.is_signed, speed.start, speed.length) == (10, "count/s", True, 40, 16)


@pytest.mark.parametrize("session", sorted(SESSIONS))
def test_session_decodes_alike(can, db, session):
    frames = 0
    kinds = set()
    with SESSIONS[session].open() as log:
        for entry in Parser(log):  # cantools' own candump reader
            frame = can.Frame(entry.frame_id, bytes(entry.data))
            env = can.decode(frame)
            # A command identifier carries commands of every length, so the DBC message is 8 bytes
            # long and shorter frames need allow_truncated.
            decoded = db.decode_message(entry.frame_id, frame.data, decode_choices=False, allow_truncated=True)
            assert decoded == _expected(can, env), str(frame)
            frames += 1
            kinds.add(env.message.NAME)
    # Every line of the log is a frame that cantools read and both decoders agreed on.
    lines = sum(1 for line in SESSIONS[session].read_text().splitlines() if line.strip())
    assert frames == lines > 300
    assert {"position_move", "velocity_move", "position_broadcast", "status_broadcast", "set_position_pid",
            "set_broadcast_policy", "get_firmware_version_reply", "supply_broadcast"} <= kinds


def test_named_values_match_enums(can, db):
    decoded = db.decode_message(0x113, bytes.fromhex("080100A020200304"))
    assert str(decoded["mode0"]) == "position" and str(decoded["mode1"]) == "hardware_fault"
    decoded = db.decode_message(0x001, bytes.fromhex("8902"), allow_truncated=True)
    assert str(decoded["command"]) == "set_control_mode" and str(decoded["set_control_mode_mode"]) == "velocity"


def test_bootloader_frames_decode_alike(can, db):
    """The bootloader class has its own DBC messages per board (HOST_TO_<BOARD>_BOOTLOADER and
    <BOARD>_BOOTLOADER_REPLY), multiplexed like the motor-control commands."""
    assert db.get_message_by_name("HOST_TO_EYES_PAN_BOOTLOADER").frame_id == 0x703
    assert db.get_message_by_name("EYES_PAN_BOOTLOADER_REPLY").frame_id == 0x730
    envelopes = [
        can.command(3, 0, can.EnterBootloader(key=0x544F4F42)),
        can.command(3, 0, can.BootloaderIdentify()),
        can.reply(3, 0, can.BootloaderIdentifyReply(board_type=can.BoardType.ROBOGENE_MOTOR_BOARD, board_id=3,
                                                    revision=ord("C"), stage=can.FirmwareStage.BOOTLOADER,
                                                    image_valid=False, version_major=1, version_minor=0)),
        can.command(3, 0, can.BootloaderErase(size=10912)),
        can.reply(3, 0, can.BootloaderEraseReply(status=can.BootStatus.OK)),
        can.command(3, 0, can.BootloaderWrite(sequence=513, data=0xDEADBEEF)),
        can.reply(3, 0, can.BootloaderWriteReply(sequence=513, status=can.BootStatus.WRONG_BOARD)),
        can.command(3, 0, can.BootloaderVerify()),
        can.reply(3, 0, can.BootloaderVerifyReply(status=can.BootStatus.CRC_MISMATCH, crc=0x495A7594)),
        can.command(3, 0, can.BootloaderStart()),
        can.reply(3, 0, can.BootloaderStartReply(status=can.BootStatus.NO_IMAGE)),
    ]
    for env in envelopes:
        frame = can.encode(env)
        decoded = db.decode_message(frame.id, frame.data, decode_choices=False, allow_truncated=True)
        assert decoded == _expected(can, can.decode(frame)), str(frame)
    status = db.decode_message(0x730, bytes.fromhex("03010206"), allow_truncated=True)
    assert str(status["command"]) == "bootloader_write_reply"
    assert str(status["bootloader_write_reply_status"]) == "wrong_board"
