# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The head model package (hardware/head-model), as `make setup` installs it into .venv: no sys.path here."""
import pytest

from robogene_head_model import params as P


@pytest.fixture(scope="session")
def params():
    return P.load()
