# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""A small reader and writer for KiCad's s-expression files.

Lists stay Python lists; atoms become Sym (bare words), str (quoted strings), int or float.
The writer is deterministic, so regenerating the design gives byte-identical files.
"""
import re


class Sym(str):
    """A bare (unquoted) word such as `symbol` or `yes`."""


_TOKEN = re.compile(r'\s*(?:(\()|(\))|"((?:[^"\\]|\\.)*)"|([^\s()"]+))', re.S)


class SexprError(ValueError):
    pass


def parse(text, origin="<text>"):
    """Parse one s-expression; errors name the origin and the line:column."""
    stack, top, pos = [], None, 0
    while True:
        m = _TOKEN.match(text, pos)
        if not m:
            if text[pos:].strip():
                raise SexprError(f"{origin}:{_where(text, pos)}: unexpected character")
            break
        pos = m.end()
        if m.group(1):
            stack.append([])
        elif m.group(2):
            if not stack:
                raise SexprError(f"{origin}:{_where(text, m.start(2))}: unbalanced ')'")
            done = stack.pop()
            if stack:
                stack[-1].append(done)
            elif top is None:
                top = done
            else:
                raise SexprError(f"{origin}:{_where(text, m.start(2))}: more than one top-level list")
        elif m.group(3) is not None:
            _append(stack, _unescape(m.group(3)), text, m.start(), origin)
        else:
            _append(stack, _atom(m.group(4)), text, m.start(), origin)
    if stack:
        raise SexprError(f"{origin}: {len(stack)} list(s) not closed at end of file")
    if top is None:
        raise SexprError(f"{origin}: no s-expression found")
    return top


def _append(stack, value, text, pos, origin):
    if not stack:
        raise SexprError(f"{origin}:{_where(text, pos)}: atom outside any list")
    stack[-1].append(value)


def _where(text, pos):
    line = text.count("\n", 0, pos) + 1
    col = pos - (text.rfind("\n", 0, pos) + 1) + 1
    return f"{line}:{col}"


def _unescape(s):
    return s.replace('\\"', '"').replace("\\n", "\n").replace("\\\\", "\\")


def _atom(word):
    if re.fullmatch(r"-?\d+", word):
        return int(word)
    if re.fullmatch(r"-?\d*\.\d+(e-?\d+)?|-?\d+e-?\d+", word):
        return float(word)
    return Sym(word)


def fmt_num(v):
    if isinstance(v, bool):
        raise TypeError("booleans are not KiCad atoms")
    if isinstance(v, int):
        return str(v)
    s = f"{v:.6f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _fmt_atom(v):
    if isinstance(v, Sym):
        return str(v)
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'
    return fmt_num(v)


def dump(node, indent=0):
    """Write a node the way KiCad lays out its files: short lists inline, long ones broken."""
    if not isinstance(node, list):
        return _fmt_atom(node)
    flat = "(" + " ".join(dump(x) for x in node) + ")"
    if len(flat) + indent <= 100 and not any(isinstance(x, list) and len(x) > 0 and isinstance(x[0], Sym)
                                              and x[0] in ("symbol", "property", "pin", "footprint", "pad")
                                              for x in node[1:]):
        return flat
    head = []
    rest = node
    while rest and not isinstance(rest[0], list):
        head.append(_fmt_atom(rest[0]))
        rest = rest[1:]
    out = "(" + " ".join(head)
    for child in rest:
        out += "\n" + "\t" * (indent + 1) + dump(child, indent + 1)
    return out + "\n" + "\t" * indent + ")"


def find(node, key):
    """Children lists of `node` whose head is `key`."""
    return [c for c in node if isinstance(c, list) and c and c[0] == key]


def find1(node, key):
    hits = find(node, key)
    return hits[0] if hits else None
