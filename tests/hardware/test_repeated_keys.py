# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""A key written twice in one of the hardware's source files is refused, naming the file, the line of the second
and the line of the first. PyYAML alone keeps the second without a word: the catalog once held a coupling entry
twice, and the first, edited later, was silently the one not read."""
import re

import pytest
import yaml

from robogene_bom import catalog
from robogene_head import docs_pictures, sequence
from robogene_head_model import params as P
from robogene_head_model import strict_yaml


def _line_of(text: str, needle: str, nth: int = 0) -> int:
    starts = [m.start() for m in re.finditer(re.escape(needle), text)]
    return text.count("\n", 0, starts[nth]) + 1


def test_the_parameter_file_refuses_a_repeated_section(tmp_path):
    text = P.DEFAULT_PATH.read_text() + "\ncameras: {model: raspberrypi-SC0872, baseline: 70}\n"
    path = tmp_path / "head.yaml"
    path.write_text(text)
    first, second = _line_of(text, "\ncameras:") + 1, _line_of(text, "\ncameras:", 1) + 1
    with pytest.raises(P.ParameterError, match=rf"^{re.escape(str(path))}:{second}:1: YAML error: "
                                               rf"duplicate key 'cameras' \(first given at line {first}\)"):
        P.load(path)


def test_the_catalog_refuses_an_entry_written_twice(tmp_path):
    text = catalog.DEFAULT_PATH.read_text()
    block = re.search(r"^  skf-626-2Z:\n(?:    .*\n)+", text, re.M).group(0)
    text = text.replace(block, block + block.replace("Deep-groove", "Shielded deep-groove"), 1)
    path = tmp_path / "catalog.yaml"
    path.write_text(text)
    first, second = (_line_of(text, "  skf-626-2Z:\n", i) for i in (0, 1))
    with pytest.raises(catalog.CatalogError, match=rf":{second}:3: YAML error: duplicate key 'skf-626-2Z' "
                                                   rf"\(first given at line {first}\)"):
        catalog.load(path)


def test_the_project_catalog_has_no_entry_twice():
    catalog.load()       # the loader itself refuses a repeated key


def test_the_assembly_sequence_refuses_a_repeated_driver(tmp_path):
    text = sequence.DEFAULT_PATH.read_text().replace(
        "drivers:\n", "drivers:\n  hex-2:        {blade: 2.4, length: 60, handle: 25}\n", 1)
    path = tmp_path / "sequence.yaml"
    path.write_text(text)
    with pytest.raises(sequence.SequenceError, match=r"YAML error: duplicate key 'hex-2' \(first given at line"):
        sequence.load([], path)


def test_the_docs_pictures_list_refuses_a_repeated_picture(tmp_path):
    path = tmp_path / "pictures.yaml"
    path.write_text("a.png: {render: front.png}\nb.png: {render: back.png}\na.png: {render: side.png}\n")
    with pytest.raises(docs_pictures.PictureError,
                       match=r"pictures.yaml:3: YAML error: duplicate key 'a.png' \(first given at line 1\)"):
        docs_pictures.load(path)


def test_a_key_merged_in_may_be_overridden_and_other_yaml_is_as_safe_load_reads_it():
    text = "base: &b {p: 1, q: 2}\nover:\n  <<: *b\n  p: 5\nlist: [1, {k: v}]\nnum: 1.5\n"
    assert strict_yaml.load(text) == yaml.safe_load(text) == {
        "base": {"p": 1, "q": 2}, "over": {"p": 5, "q": 2}, "list": [1, {"k": "v"}], "num": 1.5}


def test_a_repeated_key_inside_a_flow_mapping_in_a_list_is_refused():
    with pytest.raises(yaml.MarkedYAMLError, match="duplicate key 'k'"):
        strict_yaml.load("- {k: 1, j: 2, k: 3}\n")


def test_unsafe_tags_stay_refused():
    with pytest.raises(yaml.constructor.ConstructorError):
        strict_yaml.load("x: !!python/object/apply:os.system ['true']\n")
