# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The checked form of a CAN protocol description (a `can_protocol:` IDL file)."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional

from ..idl.errors import Mark

# Wire scalars: (size in bytes, signed, C++ type). `bool` is one byte holding 0 or 1.
SCALARS = {
    "uint8": (1, False, "std::uint8_t"), "int8": (1, True, "std::int8_t"),
    "uint16": (2, False, "std::uint16_t"), "int16": (2, True, "std::int16_t"),
    "uint32": (4, False, "std::uint32_t"), "int32": (4, True, "std::int32_t"),
    "bool": (1, False, "bool"),
}

# Units a CAN field may carry. Positions travel in encoder counts at the joint; `pwm` is a step
# of the board's PWM duty cycle (full scale in the board configuration).
CAN_UNITS = ("count", "count/s", "count/s^2", "mA", "A", "V", "ms", "s", "pwm", "Hz")


def scalar_range(name: str) -> tuple[int, int]:
    size, signed, _ = SCALARS[name]
    if name == "bool":
        return 0, 1
    bits = 8 * size
    return (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if signed else (0, (1 << bits) - 1)


@dataclass
class EnumMember:
    name: str
    value: int
    doc: str


@dataclass
class CanEnum:
    name: str
    doc: str
    scalar: str
    members: list[EnumMember]
    mark: Mark

    def member(self, value: int) -> Optional[EnumMember]:
        return next((m for m in self.members if m.value == value), None)


@dataclass
class FlagBit:
    name: str
    bit: int
    doc: str

    @property
    def value(self) -> int:
        return 1 << self.bit


@dataclass
class CanFlags:
    name: str
    doc: str
    scalar: str
    bits: list[FlagBit]
    mark: Mark

    @property
    def size(self) -> int:
        """Bytes on the wire."""
        return SCALARS[self.scalar][0]


@dataclass
class CanField:
    name: str
    scalar: str                      # the wire scalar
    enum: Optional[CanEnum] = None
    flags: Optional[CanFlags] = None
    unit: Optional[str] = None
    scale: float = 1.0
    offset: float = 0.0
    doc: str = ""
    byte: int = 0                    # offset in the frame's data
    mark: Optional[Mark] = None

    @property
    def size(self) -> int:
        return SCALARS[self.scalar][0]

    @property
    def signed(self) -> bool:
        return SCALARS[self.scalar][1]

    @property
    def scaled(self) -> bool:
        """Scaled fields are real numbers in the API (raw * scale + offset); others are integers."""
        return self.scale != 1.0 or self.offset != 0.0

    @property
    def kind(self) -> str:
        if self.enum:
            return "enum"
        if self.flags:
            return "flags"
        if self.scalar == "bool":
            return "bool"
        return "real" if self.scaled else "int"

    @property
    def type_name(self) -> str:
        return self.enum.name if self.enum else self.flags.name if self.flags else self.scalar


@dataclass
class Message:
    """One frame layout: a command's request or reply, or a broadcast."""

    name: str            # snake_case, unique in the protocol
    class_name: str
    class_value: int
    code: int            # command code (7 bits) or broadcast type (low id nibble)
    kind: str            # "request", "reply" or "broadcast"
    doc: str
    fields: list[CanField]
    length: int          # the DLC; the payload is zero-padded to it
    period_ms: Optional[float] = None
    mark: Optional[Mark] = None

    @property
    def header_bytes(self) -> int:
        return 0 if self.kind == "broadcast" else 1

    @property
    def pascal(self) -> str:
        return "".join(p.capitalize() for p in self.name.split("_"))


@dataclass
class CanClass:
    name: str
    value: int
    addressing: str      # "destination" or "message_type"
    doc: str
    messages: list[Message] = field(default_factory=list)


@dataclass
class IdField:
    name: str
    shift: int
    bits: int
    doc: str

    @property
    def max(self) -> int:
        return (1 << self.bits) - 1

    @property
    def mask(self) -> int:
        return self.max << self.shift


@dataclass
class CanProtocol:
    name: str
    version: int
    doc: str
    protocol_major: int
    protocol_minor: int
    bitrate: int
    id_layout: list[IdField]
    host: int
    first_board: int
    last_board: int
    broadcast: int
    enums: list[CanEnum]
    flags: list[CanFlags]
    classes: list[CanClass]
    file: str
    mark: Mark
    fingerprint: str = ""
    canonical: str = ""

    @property
    def messages(self) -> list[Message]:
        return [m for c in self.classes for m in c.messages]

    def id_field(self, name: str) -> IdField:
        return next(f for f in self.id_layout if f.name == name)

    def message(self, name: str) -> Optional[Message]:
        return next((m for m in self.messages if m.name == name), None)

    @property
    def broadcasts(self) -> list[Message]:
        return [m for m in self.messages if m.kind == "broadcast"]
