# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The parameter file loads, and a wrong one is refused with the key (or line:column) that is wrong."""
import copy

import pytest
import yaml

from robogene_head_model import params as P


@pytest.fixture(scope="module")
def raw():
    return yaml.safe_load(P.DEFAULT_PATH.read_text())


def _err(data):
    with pytest.raises(P.ParameterError) as info:
        P.parse(data, "head.yaml", P.DEFAULT_PATH)
    return str(info.value)


def test_loads_and_keeps_the_paper_numbers(params):
    assert params.baseline == 68
    assert params.joints["left_eye_pan"].origin[1] - params.joints["right_eye_pan"].origin[1] == 68
    assert list(params.control_limits) == list(P.CONTROL_JOINTS)
    assert params.control_limits["eyes_vergence"] == (0, 45)


def test_missing_key_is_named(raw):
    data = copy.deepcopy(raw)
    del data["joints"]["neck_yaw"]["axis"]
    assert _err(data) == "head.yaml: joints.neck_yaw.axis: missing"


def test_a_checks_own_finding_names_the_key(params):
    """Node.fail is public: a check outside params.py reports a finding on a key with the file and the key's path."""
    error = params.geometry("pulleys", "tilt").fail("flange_thickness", "too thick")
    assert isinstance(error, P.ParameterError)
    assert str(error) == f"{params.path}: geometry.pulleys.tilt.flange_thickness: too thick"
    assert not hasattr(P.Node, "_fail")


def test_wrong_type_is_named(raw):
    data = copy.deepcopy(raw)
    data["joints"]["eyes_tilt"]["origin"][2] = "eighty-two"
    assert "joints.eyes_tilt.origin[2]: expected a number" in _err(data)


def test_axis_must_be_unit(raw):
    data = copy.deepcopy(raw)
    data["joints"]["neck_roll"]["axis"] = [1, 1, 0]
    assert "joints.neck_roll.axis: must be a unit vector" in _err(data)


def test_drive_refers_to_a_listed_part_of_the_right_kind(raw):
    data = copy.deepcopy(raw)
    data["drives"]["neck_yaw"]["motor"] = "skf-626-2Z"
    assert "drives.neck_yaw.motor: 'skf-626-2Z' is a bearing, expected a motor" in _err(data)
    data["drives"]["neck_yaw"]["motor"] = "nonexistent-motor"
    assert "drives.neck_yaw.motor: 'nonexistent-motor' is not listed under purchased" in _err(data)


def test_eye_joints_must_reach_version_and_vergence(raw):
    data = copy.deepcopy(raw)
    data["control_joints"][5]["max"] = 80
    assert "joints.left_eye_pan: range" in _err(data)


def test_baseline_must_match_eye_origins(raw):
    data = copy.deepcopy(raw)
    data["cameras"]["baseline"] = 70
    assert "y = +-baseline/2" in _err(data)


def test_yaml_syntax_error_has_line_and_column(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: x\njoints: {neck_pitch: [1, 2}\n")
    with pytest.raises(P.ParameterError) as info:
        P.load(bad)
    assert str(info.value).startswith(f"{bad}:2:")


def test_geometry_problem_is_reported_by_key(raw, tmp_path, external):
    from robogene_head.parts import build_all
    data = copy.deepcopy(raw)
    data["geometry"]["eyes"]["cup_radius"] = 15   # the camera board no longer fits in the cup
    path = tmp_path / "small-eyes.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(P.ParameterError, match=r"geometry\.eyes\.cup_radius"):
        build_all(P.load(path), external)
