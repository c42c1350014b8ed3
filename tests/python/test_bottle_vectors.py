# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The shared Bottle vectors through the Python binding: the same cases the C++ tests check,
so both languages agree with YARP 3 and with each other."""
import pytest

import robogene
from vectors import expected_bottle, load

DATA = load("bottles.json")
CASES = DATA["cases"]


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_text_parses_to_expected_tree(case):
    assert robogene.Bottle.from_text(case["text"]) == expected_bottle(case["value"])


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_binary_form_is_yarp_bytes(case):
    assert expected_bottle(case["value"]).to_bytes().hex() == case["hex"]


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_bytes_decode_to_expected_tree(case):
    assert robogene.Bottle.from_bytes(bytes.fromhex(case["hex"])) == expected_bottle(case["value"])


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_rendering_is_yarp_text_and_round_trips(case):
    bottle = robogene.Bottle.from_bytes(bytes.fromhex(case["hex"]))
    assert bottle.to_text() == case["canonical_text"]
    assert robogene.Bottle.from_text(bottle.to_text()).to_bytes() == bottle.to_bytes()


@pytest.mark.parametrize("case", DATA["malformed_text"], ids=lambda c: repr(c["text"]))
def test_malformed_text_names_the_column(case):
    with pytest.raises(robogene.ParseError) as err:
        robogene.Bottle.from_text(case["text"])
    assert err.value.position == case["column"]
    assert case["message"] in str(err.value)


@pytest.mark.parametrize("case", DATA["malformed_hex"], ids=lambda c: c["hex"] or "empty")
def test_malformed_bytes_name_the_offset(case):
    with pytest.raises(robogene.ParseError) as err:
        robogene.Bottle.from_bytes(bytes.fromhex(case["hex"]))
    assert err.value.position == case["offset"]
    assert case["message"] in str(err.value)


# What real YARP 3.5 produced (see runtime/bottle/test/yarp_vectors_test.cpp, its C++ twin):
# our parser gives YARP's bytes, our decoder YARP's rendering, re-encoding the same bytes.
YARP = load("yarp3_bottles.json")
YARP_OK = [c for c in YARP if not c["name"].startswith("malformed_")]
YARP_MALFORMED = [c for c in YARP if c["name"].startswith("malformed_")]
YARP_TYPED = load("yarp3_typed_values.json")


@pytest.mark.parametrize("case", YARP_OK, ids=[c["name"] for c in YARP_OK])
def test_yarp_produced_vectors(case):
    assert robogene.Bottle.from_text(case["text"]).to_bytes().hex() == case["hex"]
    decoded = robogene.Bottle.from_bytes(bytes.fromhex(case["hex"]))
    assert decoded.to_text() == case["canonical_text"]
    assert decoded.to_bytes().hex() == case["hex"]


@pytest.mark.parametrize("case", YARP_MALFORMED, ids=[c["name"] for c in YARP_MALFORMED])
def test_what_yarp_accepts_as_malformed_we_refuse_with_a_column(case):
    with pytest.raises(robogene.ParseError) as err:
        robogene.Bottle.from_text(case["text"])
    assert "column" in str(err.value)


@pytest.mark.parametrize("case", YARP_TYPED, ids=[c["name"] for c in YARP_TYPED])
def test_yarp_typed_values(case):
    decoded = robogene.Bottle.from_bytes(bytes.fromhex(case["hex"]))
    assert decoded.to_text() == case["canonical_text"]
    assert decoded.to_bytes().hex() == case["hex"]


def test_yarp_vector_files_are_not_empty():
    assert len(YARP_OK) >= 130 and len(YARP_MALFORMED) >= 5 and len(YARP_TYPED) >= 20
