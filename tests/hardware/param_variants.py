# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Edited copies of the head parameter file: the changed and deliberately broken variants the checks are run on."""
from pathlib import Path
from typing import Callable

import yaml

from robogene_head_model.params import DEFAULT_PATH, HeadParameters, load


def edited_file(tmp_path: Path, edit: Callable[[dict], None]) -> Path:
    """The parameter file with edit(data) applied, written to tmp_path."""
    data = yaml.safe_load(DEFAULT_PATH.read_text())
    edit(data)
    path = tmp_path / "head-parameters.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return path


def edited(tmp_path: Path, edit: Callable[[dict], None]) -> HeadParameters:
    """The parameters of edited_file(tmp_path, edit), loaded (and so checked)."""
    return load(edited_file(tmp_path, edit))
