# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""A wrong CAN protocol file is refused with file:line:column and what is wrong."""
from pathlib import Path

import pytest

from robogene_codegen.idl import IdlErrors, compile_directory

ROOT = Path(__file__).resolve().parents[2]
PROTOCOL = (ROOT / "interfaces" / "idl" / "can_motor_control.yaml").read_text()
NAME = "can_motor_control.yaml"


def errors_of(tmp_path, old: str, new: str) -> tuple[list[str], str]:
    assert PROTOCOL.count(old) == 1, f"{old!r} must occur once in the protocol file"
    text = PROTOCOL.replace(old, new)
    (tmp_path / NAME).write_text(text)
    with pytest.raises(IdlErrors) as info:
        compile_directory(tmp_path, root=tmp_path)
    return [str(e) for e in info.value.errors], text


def where(text: str, needle: str, skip: int = 0) -> str:
    """line:column of the first `needle` (plus `skip` characters), as the compiler counts them."""
    at = text.index(needle) + skip
    return f"{text.count(chr(10), 0, at) + 1}:{at - text.rfind(chr(10), 0, at)}"


def line_of(text: str, needle: str, occurrence: int = 1) -> int:
    at = -1
    for _ in range(occurrence):
        at = text.index(needle, at + 1)
    return text.count("\n", 0, at) + 1


def test_the_protocol_compiles(tmp_path):
    (tmp_path / NAME).write_text(PROTOCOL)
    idl = compile_directory(tmp_path, root=tmp_path)
    proto = idl.can_protocols[0]
    assert proto.message("position_move").code == 27 and proto.message("position_move").length == 7
    assert proto.message("get_encoder_position_reply").length == 7
    assert [m.code for m in proto.broadcasts] == [1, 2, 3, 4, 7, 13]
    assert len(proto.fingerprint) == 16


def test_command_code_collision(tmp_path):
    errs, text = errors_of(tmp_path, "        code: 28\n", "        code: 27\n")
    line = line_of(text, "code: 27", 2)
    assert errs == [f"{NAME}:{line}:15: error: code collision: command code 27 is already used at line "
                    f"{line_of(text, 'code: 27')}"]


def test_payload_longer_than_a_frame(tmp_path):
    errs, text = errors_of(tmp_path, "          - {name: shift, type: uint8}\n      - name: get_position_pid\n",
                           "          - {name: shift, type: uint16}\n      - name: get_position_pid\n")
    assert errs == [f"{NAME}:{line_of(text, 'name: set_position_pid')}:15: error: 'set_position_pid' needs 9 "
                    "bytes, more than the 8 of a CAN frame"]


def test_unknown_field_type_and_unit(tmp_path):
    errs, text = errors_of(tmp_path, "- {name: voltage, type: uint16, unit: V, scale: 0.001}",
                           "- {name: voltage, type: float32, unit: furlong, scale: 0.001}")
    assert len(errs) == 1 and errs[0].startswith(f"{NAME}:{where(text, 'float32')}: error: unknown field type "
                                                 "'float32' (known: uint8, int8, uint16, int16, uint32, int32, bool, ")


def test_unknown_unit(tmp_path):
    errs, text = errors_of(tmp_path, "- {name: voltage, type: uint16, unit: V, scale: 0.001}",
                           "- {name: voltage, type: uint16, unit: furlong, scale: 0.001}")
    assert len(errs) == 1 and errs[0].startswith(f"{NAME}:{where(text, 'furlong')}: error: unknown unit "
                                                 "'furlong' (known units: count, ")


def test_enum_value_must_fit_its_wire_type(tmp_path):
    errs, text = errors_of(tmp_path, "{name: configured, value: 0xB1}", "{name: configured, value: 0x1B1}")
    assert errs == [f"{NAME}:{where(text, '0x1B1')}: error: member 'configured' = 433 does not fit the "
                    "enum's wire type uint8 (0..255)"]


def test_broadcast_type_must_fit_the_low_identifier_bits(tmp_path):
    errs, text = errors_of(tmp_path, "        code: 13\n", "        code: 16\n")
    assert errs == [f"{NAME}:{line_of(text, 'code: 16')}:15: error: broadcast type code 16 is out of range (0..15)"]


def test_identifier_fields_must_not_overlap(tmp_path):
    errs, text = errors_of(tmp_path, "{name: source, shift: 4, bits: 4}", "{name: source, shift: 3, bits: 4}")
    # source now covers bits 3..6, so destination (bits 0..3) is the one that overlaps
    assert errs == [f"{NAME}:{line_of(text, 'name: destination')}:5: error: identifier field 'destination' overlaps another "
                    "field's bits"]


def test_scaled_enum_is_refused(tmp_path):
    errs, text = errors_of(tmp_path, "          - {name: mode, type: ControlMode}\n      - name: get_encoder_position",
                           "          - {name: mode, type: ControlMode, scale: 2}\n      - name: get_encoder_position")
    assert errs == [f"{NAME}:{where(text, 'scale: 2', skip=len('scale: '))}: error: field 'mode' of type ControlMode cannot be scaled"]


def test_structure_errors_name_the_key(tmp_path):
    errs, text = errors_of(tmp_path, "        code: 46\n", "        code: 46\n        colour: red\n")
    assert errs == [f"{NAME}:{line_of(text, 'colour')}:9: error: unknown key 'colour' in classes.0.commands.11 "
                    "(allowed: code, doc, name, reply, reply_length, request, request_length)"]


def test_commands_belong_to_destination_classes(tmp_path):
    errs, text = errors_of(tmp_path, "    addressing: message_type\n    doc: What each board",
                           "    addressing: destination\n    doc: What each board")
    assert errs == [f"{NAME}:{line_of(text, 'broadcasts:')}:5: error: class 'periodic_motor_control' addresses "
                    "a destination, so it carries commands, not broadcasts"]
