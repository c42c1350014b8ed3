# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The joint configuration for the boards follows the parameter file."""
import copy

import pytest
import yaml

from robogene_head_model import joint_config, params as P


def test_reductions_include_the_belts(params):
    cfg = joint_config.config(params)
    j = {e["name"]: e for e in cfg["joints"]}
    assert j["neck_pitch"]["reduction"] == 66
    assert j["neck_yaw"]["reduction"] == pytest.approx(66 * 20 / 14)   # the 22/7 66:1 and the yaw belt, 14T to 20T
    assert j["neck_roll"]["reduction"] == 246
    assert j["eyes_tilt"]["reduction"] == pytest.approx(43 * 24 / 14)   # the 16/7 43:1 and the tilt belt
    assert j["left_eye_pan"]["motor_counts_per_joint_degree"] == pytest.approx(4 * 512 * 43 / 360)
    assert "joint_encoder" not in j["left_eye_pan"]
    assert [c["name"] for c in cfg["control_board"]] == list(P.CONTROL_JOINTS)
    assert cfg["couplings"]["neck_pitch+neck_roll"]["type"] == "none"   # serial neck: one motor per joint


def test_a_parameter_change_travels_to_the_config(tmp_path):
    data = yaml.safe_load(P.DEFAULT_PATH.read_text())
    data = copy.deepcopy(data)
    data["geometry"]["pulleys"]["yaw"]["joint_teeth"] = 40
    path = tmp_path / "p.yaml"
    path.write_text(yaml.safe_dump(data))
    cfg = joint_config.config(P.load(path))
    assert {e["name"]: e for e in cfg["joints"]}["neck_yaw"]["reduction"] == pytest.approx(66 * 40 / 14)
