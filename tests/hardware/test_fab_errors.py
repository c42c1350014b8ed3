# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""How fab.py turns a check's or a step's own error into the BuildError that stops `make fab`: the message is the
error's own, word for word, with no traceback of the error chained to it; any other error is not swallowed."""
import pytest

from robogene_head import fab
from robogene_head.bearing_loads import BearingLoadError
from robogene_head_model.params import ParameterError


def test_a_listed_error_becomes_a_build_error_with_its_own_message():
    with pytest.raises(fab.BuildError) as caught:
        with fab._fails_build(ParameterError, BearingLoadError):
            raise BearingLoadError("neck_yaw_bearing_lower: 480 N against C0 440 N")
    assert str(caught.value) == "neck_yaw_bearing_lower: 480 N against C0 440 N"
    assert caught.value.__suppress_context__ and caught.value.__cause__ is None


def test_an_unlisted_error_passes_through_unchanged():
    with pytest.raises(KeyError) as caught:
        with fab._fails_build(BearingLoadError):
            raise KeyError("neck_roll")
    assert type(caught.value) is KeyError



def test_a_torque_path_too_weak_stops_the_build_with_its_table(tmp_path):
    """fab.py enforces the torque paths as it does the other checks: a yaw stage on MXL stock (its belt 0.085 of the
    0.373 N m peak) is the TorquePathError's message, table and all."""
    from robogene_head import torque_path
    from param_variants import edited

    def mxl(data):
        data["geometry"]["pulleys"]["yaw"].update(belt="mxl-belt-6mm", pitch=2.032, width=8, flange_thickness=0.6)
    report = torque_path.analyse(edited(tmp_path, mxl))
    with pytest.raises(fab.BuildError, match=r"^torque path elements below the required margin 1\.5: neck_yaw\[3\] "
                                             r"belt") as caught:
        with fab._fails_build(torque_path.TorquePathError):
            torque_path.enforce(report)
    assert torque_path.format_table(report) in str(caught.value)
