# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The IDL loader and compiler under hostile input (issue 11), with Hypothesis: any text, and
the project's own IDL files with one value replaced by something random (structure-aware: the
mutation lands inside a file the compiler otherwise accepts). Whatever comes, compilation ends
in an Idl or in IdlErrors whose every error names a place inside the file; never another
exception, never a hang."""
from __future__ import annotations

import shutil
from pathlib import Path

import yaml
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from robogene_codegen.idl import IdlErrors, compile_files
from robogene_codegen.idl.loader import load

ROOT = Path(__file__).resolve().parents[2]
IDL = ROOT / "interfaces" / "idl"
FILES = sorted(p.name for p in IDL.glob("*.yaml"))

scalars = st.one_of(st.none(), st.booleans(), st.integers(-(2**40), 2**40), st.floats(allow_nan=True),
                    st.text(max_size=12), st.sampled_from(["int32", "float64", "vocab", "string", "list", "ok",
                                                           "[set]", "", "-", "*", "is", "Mode"]))
values = st.recursive(scalars, lambda inner: st.one_of(st.lists(inner, max_size=3),
                                                        st.dictionaries(st.text(max_size=8), inner, max_size=3)),
                      max_leaves=8)


def places(data, path=()):
    """Every path into a loaded document: (key or index, ...)."""
    yield path
    if isinstance(data, dict):
        for k, v in data.items():
            yield from places(v, path + (k,))
    elif isinstance(data, list):
        for i, v in enumerate(data):
            yield from places(v, path + (i,))


def replaced(data, path, value):
    if not path:
        return value
    head, rest = path[0], path[1:]
    if isinstance(data, dict):
        return {k: (replaced(v, rest, value) if k == head else v) for k, v in data.items()}
    return [replaced(v, rest, value) if i == head else v for i, v in enumerate(data)]


def expect_clean_outcome(paths, texts):
    try:
        compile_files(paths)
    except IdlErrors as e:
        assert e.errors
        for err in e.errors:
            assert err.message
            lines = texts.get(err.mark.file)
            if lines is not None:
                assert 1 <= err.mark.line <= max(lines, 1) + 1, (str(err), lines)


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=300))
def test_any_text_loads_or_is_refused_with_a_place(text):
    try:
        load("x.yaml", text)
    except IdlErrors as e:
        assert all(err.mark.file == "x.yaml" and err.mark.line >= 1 and err.message for err in e.errors)


@pytest.mark.timeout(300)  # each example compiles every IDL file of the project
@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture,
                                                                   HealthCheck.too_slow])
@given(st.sampled_from(FILES), st.data(), values)
def test_one_value_replaced_in_a_real_idl_file_compiles_or_is_refused_with_a_place(tmp_path_factory, name, data,
                                                                                 value):
    work = tmp_path_factory.mktemp("idl")
    for f in FILES:
        shutil.copy(IDL / f, work / f)
    original = yaml.safe_load((IDL / name).read_text(encoding="utf-8"))
    path = data.draw(st.sampled_from(list(places(original))))
    text = yaml.safe_dump(replaced(original, path, value), sort_keys=False, allow_unicode=True)
    (work / name).write_text(text, encoding="utf-8")
    paths = sorted(work.glob("*.yaml"))
    texts = {str(p): len(p.read_text(encoding="utf-8").splitlines()) for p in paths}
    expect_clean_outcome(paths, texts)
