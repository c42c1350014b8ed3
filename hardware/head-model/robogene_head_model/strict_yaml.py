# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""YAML as the hardware's source files are read: safe types only, and a key given twice in one mapping is an error.

PyYAML keeps the last of two equal keys without a word, so a part entry written twice (or pasted over an older
one) silently replaces the first. Here the second raises yaml.constructor.ConstructorError, a MarkedYAMLError
whose mark is the repeated key and whose problem names the line of the first: each loader's existing handler
reports it as path:line:column like any other YAML error."""
from __future__ import annotations

import yaml
from yaml.constructor import ConstructorError


class _StrictLoader(yaml.SafeLoader):
    def construct_mapping(self, node, deep=False):
        if isinstance(node, yaml.MappingNode):
            # the keys written in this mapping: a key merged in (<<) may be overridden, as YAML allows
            first: dict = {}
            for key_node, _ in node.value:
                if key_node.tag == "tag:yaml.org,2002:merge":
                    continue
                key = self.construct_object(key_node, deep=True)
                try:
                    earlier = first.get(key)
                except TypeError:                 # an unhashable key: SafeLoader's own error follows
                    continue
                if earlier is not None:
                    raise ConstructorError("while constructing a mapping", node.start_mark,
                                           f"duplicate key {key!r} (first given at line {earlier.line + 1})",
                                           key_node.start_mark)
                first[key] = key_node.start_mark
        return super().construct_mapping(node, deep)


def load(text: str):
    """The document in text, as yaml.safe_load gives it, but for a repeated key."""
    return yaml.load(text, Loader=_StrictLoader)   # noqa: S506 (a SafeLoader subclass)
