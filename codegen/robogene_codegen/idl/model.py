# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The checked, resolved form of the IDL that every emitter reads."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Optional, Union

from .errors import Mark

# Built-in scalar types. `joint` is an int32 axis index; `image_rgb` only travels on streams.
BUILTIN_TYPES = ("joint", "int32", "float64", "bool", "string", "vocab", "image_rgb")

# Names that would not compile as C++ or Python identifiers in the generated code.
RESERVED_WORDS = frozenset("""
alignas alignof and and_eq asm auto bitand bitor bool break case catch char char8_t char16_t
char32_t class compl concept const consteval constexpr constinit const_cast continue co_await
co_return co_yield decltype default delete do double dynamic_cast else enum explicit export
extern false float for friend goto if inline int long mutable namespace new noexcept not not_eq
nullptr operator or or_eq private protected public register reinterpret_cast requires return
short signed sizeof static static_assert static_cast struct switch template this thread_local
throw true try typedef typeid typename union unsigned using virtual void volatile wchar_t while
xor xor_eq
False None True as assert async await def del elif except finally from global import in is
lambda nonlocal pass raise with yield self
""".split())

# Units an argument or result may carry (SI or YARP's customary ones); anything else is a typo.
UNITS = ("count", "deg", "deg/s", "deg/s^2", "rad", "rad/s", "rad/s^2", "m", "m/s", "m/s^2",
         "Nm", "N", "A", "V", "W", "s", "ms", "Hz", "px", "fraction", "percent")


@dataclass
class EnumMember:
    name: str
    value: Union[int, str]  # an int32, or the characters of a vocab
    doc: str
    mark: Mark


@dataclass
class EnumType:
    name: str
    doc: str
    wire: str  # "vocab" or "int32"
    members: list[EnumMember]
    mark: Mark

    def member(self, name: str) -> Optional[EnumMember]:
        return next((m for m in self.members if m.name == name), None)


@dataclass
class StructType:
    name: str
    doc: str
    fields: list["Field"]
    mark: Mark


@dataclass
class TypeRef:
    name: str
    enum: Optional[EnumType] = None
    struct: Optional[StructType] = None

    @property
    def kind(self) -> str:
        return "enum" if self.enum else "struct" if self.struct else "builtin"


@dataclass
class Field:
    name: str
    type: TypeRef
    unit: Optional[str]
    doc: str
    mark: Mark
    per_axis: bool = False      # a list with one entry per axis (all-axes forms)
    has_default: bool = False
    default: Any = None


@dataclass
class Method:
    """One callable form: a single-axis or plain method, or the all-axes form derived from one."""

    interface: str
    name: str          # unique within the interface; the Python name
    cpp_name: str      # the C++ name (all-axes forms may overload the single-axis name)
    doc: str
    wire: Optional[tuple]  # vocab path; None for local-only methods
    echo: Union[int, str, None]  # request index the [is] reply repeats, or a vocab it carries
    args: list[Field]
    results: list[Field]
    mark: Mark
    form: str = "single"   # "single", "axis" (has an all-axes twin) or "all"
    twin: Optional[str] = None  # name of the other form
    stamp: bool = True     # a query's reply carries [tsta] <n> <t> (YARP's appendTimeStamp)
    # A query's own reply head instead of [is] <echo> and the [tsta]/[ok] tail (YARP's frame
    # grabbers): ints repeat a request item, strings are vocabs, "#vocab" a vocab's code as int32.
    reply_head: Optional[tuple] = None

    @property
    def reply(self) -> str:
        return "value" if self.results else "status"


@dataclass
class Interface:
    name: str
    version: int
    doc: str
    methods: list[Method]
    file: str
    mark: Mark
    enums: list[EnumType] = field(default_factory=list)
    structs: list[StructType] = field(default_factory=list)
    fingerprint: str = ""
    canonical: str = ""

    def method(self, name: str) -> Optional[Method]:
        return next((m for m in self.methods if m.name == name), None)


@dataclass
class Protocol:
    wire: tuple
    reply: str
    version: tuple


@dataclass
class Stream:
    name: str
    port: str
    doc: str
    interface: str
    method: Method
    period: float


@dataclass
class Command:
    """A streaming port taking (head) (values) messages with no reply: the head is a request path
    without `prefix`, the values its arguments (YARP 3's command:i, a PortablePair)."""

    port: str
    doc: str
    prefix: tuple
    routes: list  # [(head path, Method)]: the path after the prefix, or an alias's head
    aliases: list = None  # [(head path, Method)]: heads that are not a path of the service

    @property
    def alias_heads(self) -> list:
        return [head for head, _ in self.aliases or []]


@dataclass
class Service:
    name: str
    version: int
    doc: str
    rpc_port: str
    interfaces: list[Interface]
    protocol: Optional[Protocol]
    introspection: Optional[tuple]
    streams: list[Stream]
    command: Optional[Command]
    file: str
    mark: Mark
    fingerprint: str = ""
    canonical: str = ""
    # "stamped": control-board replies ([ok]/[fail], [is] ... [tsta] n t [ok]); "scoped": YARP's
    # frame-grabber replies (a failure [nak]; a command's success an empty bottle unless
    # command_reply says otherwise).
    replies: str = "stamped"
    # A scoped command's reply: request items by index and "result" (int32 1 done, 0 refused),
    # as YARP 3.12.3's frame grabbers answer a set ([fgc] [set] 1). None: the empty bottle.
    command_reply: Optional[tuple] = None


@dataclass
class Idl:
    interfaces: list[Interface]
    services: list[Service]
    enums: list[EnumType]
    structs: list[StructType]
    files: list[str]
    can_protocols: list = field(default_factory=list)   # robogene_codegen.can.model.CanProtocol
    board_configs: list = field(default_factory=list)   # robogene_codegen.can.board_config.BoardConfig

    def interface(self, name: str) -> Optional[Interface]:
        return next((i for i in self.interfaces if i.name == name), None)
