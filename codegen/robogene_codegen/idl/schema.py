# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Structural validation against interfaces/idl/idl.schema.json, errors placed by source mark."""
from __future__ import annotations

import json
from functools import lru_cache
from pathlib import Path

import jsonschema

from .errors import IdlError
from .loader import Document

KIND_KEYS = ("interface", "service", "types", "can_protocol", "board_config")


@lru_cache(maxsize=4)
def validator(schema_path: str) -> jsonschema.protocols.Validator:
    # The schema itself is checked against its metaschema by tests/codegen (test_idl_schema_is_valid),
    # not on every run: that check costs more CPU than validating every IDL file.
    schema = json.loads(Path(schema_path).read_text(encoding="utf-8"))
    return jsonschema.validators.validator_for(schema)(schema)


def validate(doc: Document, schema_path: str) -> list[IdlError]:
    if not isinstance(doc.data, dict):
        return [IdlError(doc.mark(()), "an IDL file is a mapping (key: value lines) at top level")]
    errors = []
    for err in validator(schema_path).iter_errors(doc.data):
        errors.extend(_explain(doc, err))
    return errors


def _where(path) -> str:
    return ".".join(str(p) for p in path) or "the file"


def _explain(doc: Document, err: jsonschema.ValidationError) -> list[IdlError]:
    path = tuple(err.absolute_path)
    if err.validator == "additionalProperties":
        allowed = sorted(err.schema.get("properties", {}))
        extras = sorted(set(err.instance) - set(allowed))
        return [IdlError(doc.key_mark(path + (k,)),
                         f"unknown key '{k}' in {_where(path)} (allowed: {', '.join(allowed)})")
                for k in extras]
    if err.validator == "oneOf" and not path:
        kinds = [k for k in KIND_KEYS if k in err.instance]
        if len(kinds) != 1:
            return [IdlError(doc.mark(()), "a file describes exactly one of: an interface "
                             "('interface:'), a service ('service:'), shared types ('types:'), a CAN "
                             "protocol ('can_protocol:') or a board configuration ('board_config:'); "
                             f"found {', '.join(kinds) or 'none'}")]
        needs = {"interface": ("interface", "version", "doc", "methods"),
                 "service": ("service", "version", "doc", "interfaces", "rpc_port"),
                 "types": ("types",),
                 "can_protocol": ("can_protocol", "version", "doc", "protocol_version", "bitrate",
                                  "id_layout", "addresses", "classes"),
                 "board_config": ("board_config", "doc", "protocol", "parameters", "timeouts",
                                  "broadcasts")}[kinds[0]]
        allowed_extra = {"interface": (), "service": ("protocol", "introspection", "streams", "command", "replies",
                                                     "command_reply"),
                         "types": (), "can_protocol": ("enums", "flags"), "board_config": ()}[kinds[0]]
        missing = [k for k in needs if k not in err.instance]
        if missing:
            return [IdlError(doc.mark(()), f"{kinds[0]} file is missing: {', '.join(missing)}")]
        stray = [k for k in err.instance if k not in needs + allowed_extra + ("idl", "doc")]
        return [IdlError(doc.key_mark((k,)), f"key '{k}' does not belong in a {kinds[0]} file")
                for k in stray] or [IdlError(doc.mark(()), err.message)]
    if err.validator == "required":
        return [IdlError(doc.mark(path), f"{_where(path)}: {err.message}")]
    if err.validator == "const" and path == ("idl",):
        return [IdlError(doc.mark(path), f"unsupported IDL language version {err.instance!r} "
                         "(this compiler reads version 1)")]
    return [IdlError(doc.mark(path), f"{_where(path)}: {err.message}")]
