# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The package's joint configuration is the head model's (tests/head_model tests the model itself)."""
import json

from robogene_head_model import joint_config


def test_package_has_the_config(fab, params):
    assert json.loads((fab / "config" / "head-joints.json").read_text()) == json.loads(json.dumps(joint_config.config(params)))
