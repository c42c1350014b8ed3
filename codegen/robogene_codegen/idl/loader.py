# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""YAML to plain data plus the source mark of every key and value.

PyYAML's composer keeps marks on nodes; its constructor drops them. We walk the node tree
ourselves so that every later error can point at the line and column of what is wrong, and so
that a repeated key (which PyYAML would silently overwrite) is reported instead.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Optional

import yaml

from .errors import IdlError, IdlErrors, Mark

Path = tuple  # of str keys and int indices, as jsonschema reports them


@dataclass
class Document:
    file: str
    data: Any
    value_marks: dict = field(default_factory=dict)  # path -> Mark of the value
    key_marks: dict = field(default_factory=dict)    # path -> Mark of the key naming it

    def mark(self, path: Path) -> Mark:
        """The mark of `path`, or of its closest enclosing value that has one."""
        path = tuple(path)
        while path not in self.value_marks and path:
            path = path[:-1]
        return self.value_marks.get(path, Mark(self.file, 1, 1))

    def key_mark(self, path: Path) -> Mark:
        return self.key_marks.get(tuple(path)) or self.mark(path)


def _mark(file: str, node: yaml.Node) -> Mark:
    return Mark(file, node.start_mark.line + 1, node.start_mark.column + 1)


# libyaml's parser when PyYAML was built with it (it is on Debian and in the wheels): same marks,
# several times faster, which keeps a whole regeneration well under a second.
_Loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


def load(file: str, text: str) -> Document:
    doc = Document(file, None)
    loader = _Loader(text)
    try:
        node = loader.get_single_node()
        if node is None:
            raise IdlErrors([IdlError(Mark(file, 1, 1), "the file is empty")])
        errors: list[IdlError] = []
        doc.data = _convert(loader, doc, node, (), errors)
        if errors:
            raise IdlErrors(errors)
    except yaml.MarkedYAMLError as exc:
        where = exc.problem_mark or exc.context_mark
        line, col = (where.line + 1, where.column + 1) if where else (1, 1)
        what = " ".join(p for p in (exc.context, exc.problem) if p)
        raise IdlErrors([IdlError(Mark(file, line, col), f"YAML syntax: {what}")]) from None
    except yaml.YAMLError as exc:  # reader errors (bad bytes) carry a position, not a mark
        pos = getattr(exc, "position", 0)
        raise IdlErrors([IdlError(Mark(file, 1, 1), f"YAML: {exc} (character {pos})")]) from None
    finally:
        loader.dispose()
    return doc


MAX_DEPTH = 32  # far deeper than any IDL file needs; guards the recursion below


def _convert(loader, doc: Document, node: yaml.Node, path: Path,
             errors: list[IdlError], seen: Optional[set] = None) -> Any:
    seen = set() if seen is None else seen
    doc.value_marks[path] = _mark(doc.file, node)
    if isinstance(node, (yaml.MappingNode, yaml.SequenceNode)):
        # Aliases (*name) would let a small file expand exponentially; the IDL has no use for them.
        if id(node) in seen:
            errors.append(IdlError(_mark(doc.file, node), "this value is reused through an alias (*name); aliases are not allowed in IDL files"))
            return None
        seen.add(id(node))
        if len(path) > MAX_DEPTH:
            errors.append(IdlError(_mark(doc.file, node), f"nested more than {MAX_DEPTH} levels deep"))
            return None
    if isinstance(node, yaml.MappingNode):
        loader.flatten_mapping(node)  # resolves `<<` merge keys
        out: dict = {}
        for key_node, value_node in node.value:
            key = loader.construct_object(key_node, deep=True)
            if not isinstance(key, str):
                errors.append(IdlError(_mark(doc.file, key_node), f"keys must be names, not {key!r}"))
                continue
            if key in out:
                first = doc.key_marks[path + (key,)]
                errors.append(IdlError(_mark(doc.file, key_node),
                                       f"duplicate key '{key}' (first given at line {first.line})"))
                continue
            doc.key_marks[path + (key,)] = _mark(doc.file, key_node)
            out[key] = _convert(loader, doc, value_node, path + (key,), errors, seen)
        return out
    if isinstance(node, yaml.SequenceNode):
        return [_convert(loader, doc, item, path + (i,), errors, seen) for i, item in enumerate(node.value)]
    return loader.construct_object(node, deep=True)
