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

