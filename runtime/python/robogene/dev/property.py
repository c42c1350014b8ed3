# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Property: the configuration a device's open() receives, from .ini files (with [groups]),
`--key value` command lines (`--group::key` inside a group), bottles of (key value...) lists or
dicts. Every entry remembers where it came from, so a bad value is reported as
"motor.ini:12: key 'axes': ..."."""
from __future__ import annotations

import math
import re
from typing import Any, Dict, Iterable, List, Optional

_TOKEN = re.compile(r'\s*(?:(?P<open>\()|(?P<close>\))|"(?P<quoted>(?:[^"\\]|\\.)*)"|(?P<word>[^\s()"]+))')
_INT = re.compile(r"^[+-]?(?:0[xX][0-9a-fA-F]+|\d+)$")
_FLOAT = re.compile(r"^[+-]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][+-]?\d+)?$|^[+-]?(?:inf|nan)$")


class ConfigError(ValueError):
    """A configuration value that is missing, malformed or out of range; the message names where."""


def _word(text: str) -> Any:
    if _INT.match(text):
        try:  # a leading 0 means octal, as in YARP (strtoll base 0); 09 is then not a number
            return int(text, 0) if not re.match(r"^[+-]?0\d", text) else int(text, 8)
        except ValueError:
            return text
    if _FLOAT.match(text):
        return float(text)
    if text in ("true", "false"):
        return text == "true"
    return text


def parse_values(text: str, where: str, column: int = 1) -> List[Any]:
    """Values in the bottle text syntax: numbers, words, "quoted strings" and (nested lists)."""
    stack: List[List[Any]] = [[]]
    opened: List[int] = []
    pos = 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None:
            if text[pos:].strip() == "":
                break
            raise ConfigError(f"{where}:{column + pos}: cannot read {text[pos:]!r}")
        start = m.start(m.lastgroup) if m.lastgroup != "quoted" else m.start("quoted") - 1
        if m.group("open"):
            stack.append([])
            opened.append(start)
        elif m.group("close"):
            if len(stack) == 1:
                raise ConfigError(f"{where}:{column + start}: ')' without a matching '('")
            inner = stack.pop()
            opened.pop()
            stack[-1].append(inner)
        elif m.group("quoted") is not None:
            stack[-1].append(re.sub(r"\\(.)", r"\1", m.group("quoted")))
        else:
            stack[-1].append(_word(m.group("word")))
        pos = m.end()
    if len(stack) > 1:
        raise ConfigError(f"{where}:{column + opened[-1]}: '(' has no matching ')'")
    return stack[0]


def _strip_comment(line: str) -> str:
    quoted = False
    i = 0
    while i < len(line):
        c = line[i]
        if c == "\\" and quoted:
            i += 1
        elif c == '"':
            quoted = not quoted
        elif not quoted and (c == "#" or line.startswith("//", i)):
            return line[:i]
        i += 1
    return line


def _is_key(v: Any) -> bool:
    return v.is_string() or v.is_vocab()


def _key_text(v: Any) -> str:
    return v.as_string() if v.is_string() else v.as_vocab_text()


def _python_value(v: Any) -> Any:
    """A bottle value as the ini and command-line readers give it."""
    if v.is_list():
        inner = v.as_list()
        return [_python_value(inner[k]) for k in range(len(inner))]
    if v.is_int():
        return v.as_int()
    if v.is_float():
        return v.as_float()
    if v.is_string():
        return v.as_string()
    if v.is_vocab():
        return v.as_vocab_text()
    if v.is_blob():
        return v.as_bytes()
    return None


class Property:
    def __init__(self, source: str = "configuration"):
        self._source = source
        self._entries: Dict[str, tuple] = {}  # key -> (values list, origin)
        self._groups: Dict[str, "Property"] = {}

    # ---- filling ----------------------------------------------------------------------------

    @classmethod
    def from_ini(cls, text: str, source_name: str) -> "Property":
        root = cls(source_name)
        current = root
        for number, raw in enumerate(text.split("\n"), start=1):
            where = f"{source_name}:{number}"
            line = _strip_comment(raw).rstrip(" \t\r")
            stripped = line.lstrip(" \t")
            if not stripped:
                continue
            column = len(line) - len(stripped) + 1
            if stripped.startswith("["):
                if not stripped.endswith("]") or len(stripped) < 3:
                    raise ConfigError(f"{where}:{column}: a group header is [name], got {stripped!r}")
                current = root.add_group(stripped[1:-1].strip(), where)
                continue
            m = re.match(r"(\S+)[ \t]*(.*)", stripped)
            key, rest = m.group(1), m.group(2)
            values = parse_values(rest, where, column + m.start(2)) if rest else [True]
            if current.check(key):
                raise ConfigError(f"{where}:{column}: key {key!r} is already set at {current.origin(key)}")
            current.put_values(key, values, where)
        return root

    @classmethod
    def from_ini_file(cls, path: str) -> "Property":
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except OSError as exc:
            raise ConfigError(f"{path}: cannot open the configuration file ({exc.strerror})") from None
        except UnicodeDecodeError as exc:
            raise ConfigError(f"{path}: not UTF-8 text (byte {exc.start})") from None
        return cls.from_ini(text, path)

    @classmethod
    def from_command_line(cls, args: Iterable[str]) -> "Property":
        args = list(args)
        root = cls("command line")
        i = 0
        while i < len(args):
            where = f"command line argument {i + 1}"
            arg = args[i]
            if len(arg) < 3 or not arg.startswith("--"):
                raise ConfigError(f"{where}: expected --key, got {arg!r}")
            key, target = arg[2:], root
            if "::" in key:
                group, key = key.split("::", 1)
                target = root.add_group(group, where)
            i += 1
            values: List[Any] = []
            while i < len(args) and not (len(args[i]) > 2 and args[i].startswith("--")):
                one = parse_values(args[i], f"command line argument {i + 1}")
                values.append(one[0] if len(one) == 1 else args[i])
                i += 1
            target.put_values(key, values or [True], where)
        return root

    @classmethod
    def from_bottle(cls, bottle: Any, source_name: str = "bottle") -> "Property":
        """From a robogene.Bottle of (key value...) lists, as the C++ Property::from_bottle:
        (key (k v...) (k v...)) is a group, (key) a flag (True); vocabs become their text."""
        root = cls(source_name)
        for i in range(len(bottle)):
            where = f"{source_name} item {i}"
            item = bottle[i]
            entry = item.as_list() if item.is_list() else None
            if entry is None or len(entry) == 0 or not _is_key(entry[0]):
                raise ConfigError(f"{where}: expected (key value...), got {item.to_text()}")
            key = _key_text(entry[0])
            rest = [entry[k] for k in range(1, len(entry))]
            if rest and all(v.is_list() and len(v.as_list()) > 0 and _is_key(v.as_list()[0]) for v in rest):
                inner = type(bottle)()
                for v in rest:
                    inner.add(v)
                root.add_group(key, where).merge(cls.from_bottle(inner, where))
                continue
            root.put_values(key, [_python_value(v) for v in rest] or [True], where)
        return root

    @classmethod
    def from_dict(cls, data: dict, source_name: str = "dict") -> "Property":
        root = cls(source_name)
        for key, value in data.items():
            if isinstance(value, dict):
                root.add_group(key, source_name).merge(cls.from_dict(value, f"{source_name}[{key!r}]"))
            else:
                root.put(key, value, f"{source_name}[{key!r}]")
        return root

    def put(self, key: str, value: Any, origin: str = "set by program") -> None:
        self.put_values(key, [value], origin)

    def put_values(self, key: str, values: List[Any], origin: str) -> None:
        self._entries[key] = (list(values), origin)

    def add_group(self, name: str, origin: str = "set by program") -> "Property":
        if name not in self._groups:
            self._groups[name] = Property(origin)
        return self._groups[name]

    def merge(self, other: "Property") -> None:
        self._entries.update(other._entries)
        for name, group in other._groups.items():
            self.add_group(name, group.source()).merge(group)

    # ---- reading ----------------------------------------------------------------------------

    def find(self, key: str) -> Any:
        """The single value of `key`, a list when it has several, None when absent."""
        entry = self._entries.get(key)
        if entry is None:
            return None
        values = entry[0]
        return values[0] if len(values) == 1 else list(values)

    def check(self, key: str) -> bool:
        return key in self._entries

    def find_group(self, name: str) -> Optional["Property"]:
        return self._groups.get(name)

    def origin(self, key: str) -> str:
        entry = self._entries.get(key)
        return entry[1] if entry else ""

    def source(self) -> str:
        return self._source

    def keys(self) -> List[str]:
        return sorted(self._entries)

    def _fail(self, key: str, what: str):
        raise ConfigError(f"{self.origin(key)}: key {key!r}: {what}")

    def require(self, key: str) -> Any:
        if not self.check(key):
            raise ConfigError(f"{self.source()}: missing key {key!r}")
        return self.find(key)

    def get_string(self, key: str, fallback: str) -> str:
        v = self.find(key)
        if v is None:
            return fallback
        if isinstance(v, str):
            return v
        self._fail(key, f"expected a word or a \"string\", got {v!r}")

    def get_int(self, key: str, fallback: int, low: int, high: int) -> int:
        v = self.find(key)
        if v is None:
            return fallback
        if isinstance(v, bool) or not isinstance(v, int):
            self._fail(key, f"expected an integer, got {v!r}")
        if not low <= v <= high:
            self._fail(key, f"{v} is outside [{low}, {high}]")
        return v

    def get_float(self, key: str, fallback: float, low: float, high: float) -> float:
        v = self.find(key)
        if v is None:
            return fallback
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            self._fail(key, f"expected a number, got {v!r}")
        if not math.isfinite(v) or not low <= v <= high:
            self._fail(key, f"{v!r} is outside [{low!r}, {high!r}]")
        return float(v)

    def get_bool(self, key: str, fallback: bool) -> bool:
        v = self.find(key)
        if v is None:
            return fallback
        if isinstance(v, bool):
            return v
        if v in (0, 1):
            return bool(v)
        self._fail(key, f"expected true or false, got {v!r}")
