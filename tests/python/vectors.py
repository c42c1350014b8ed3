# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Loads the shared Bottle test vectors and builds the expected value trees as robogene objects."""
import json
from pathlib import Path

import robogene

VECTORS = Path(__file__).resolve().parents[1] / "vectors"


def load(name):
    return json.loads((VECTORS / name).read_text(encoding="utf-8"))


def expected_value(item):
    """{"int32": 1} -> Value.int32(1); {"list": [...]} -> nested list; {"blob": "00ff"} -> blob."""
    ((kind, payload),) = item.items()
    if kind == "list":
        return robogene.Value.list([expected_value(x) for x in payload])
    if kind == "blob":
        return robogene.Value.blob(bytes.fromhex(payload))
    if kind in ("float32", "float64") and isinstance(payload, str):
        payload = float(payload)  # "inf", "-inf", "nan" are spelled as strings in JSON
    return getattr(robogene.Value, kind)(payload)


def expected_bottle(tree):
    return robogene.Bottle([expected_value(x) for x in tree])
