# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""test_motor's PID offset, enable, disable and reset, as the C++ test_motor_pid_switches.cpp: the
model has three loops (position, velocity, torque), all enabled at open, and no current loop
(these requests refuse it; its gains, offset included, are still kept). setPidOffset sets the
offset of the gains; disablePid frees an axis that runs the loop (idle) and, until enablePid, no
request may make the axis run it (TestMotor._set_axis/_set_all refuse); resetPid makes what a
running loop measures its reference (position: hold where it is; velocity: keep the present
velocity; torque: nothing to do), and accepts a loop its axis does not run."""
from __future__ import annotations

import dataclasses
import math
from typing import Optional

from ..generated import ControlMode, PidType

LOOPS = (PidType.POSITION, PidType.VELOCITY, PidType.TORQUE)
_RUNS = {ControlMode.POSITION: PidType.POSITION, ControlMode.VELOCITY: PidType.VELOCITY,
         ControlMode.TORQUE: PidType.TORQUE}


def _loop_type(pidtype) -> Optional[PidType]:
    try:
        t = PidType(pidtype)
    except ValueError:
        return None
    return t if t in LOOPS else None


class PidSwitches:
    """Mixed into TestMotor, whose lock, axes, modes, gains (_pids) and helpers it uses."""

    def _reset_switches(self, n: int) -> None:
        self._enabled = [{t: True for t in LOOPS} for _ in range(n)]

    def _loop_allowed(self, i: int, mode) -> bool:
        """False when axis i, in `mode`, would run a disabled loop; with the lock held."""
        t = _RUNS.get(ControlMode(mode))
        return t is None or self._enabled[i][t]

    def setPidOffset(self, pidtype: PidType, j: int, v: float) -> bool:
        try:
            t = PidType(pidtype)
        except ValueError:
            return False
        if not isinstance(v, (int, float)) or isinstance(v, bool) or not math.isfinite(v):
            return False

        def set_offset(a, i: int) -> bool:
            self._pids[i][t] = dataclasses.replace(self._pids[i][t], offset=float(v))
            return True
        return self._on_axis(j, set_offset) is True

    def enablePid(self, pidtype: PidType, j: int) -> bool:
        t = _loop_type(pidtype)
        return t is not None and self._on_axis(j, lambda a, i: self._enabled[i].__setitem__(t, True) or True) is True

    def disablePid(self, pidtype: PidType, j: int) -> bool:
        t = _loop_type(pidtype)

        def disable(a, i: int) -> bool:
            self._enabled[i][t] = False
            if self._loop(t, a, i) is not None:  # it drives the axis: free the axis where it is
                a.idle()
                self._modes[i] = ControlMode.IDLE
            return True
        return t is not None and self._on_axis(j, disable) is True

    def resetPid(self, pidtype: PidType, j: int) -> bool:
        t = _loop_type(pidtype)

        def reset(a, i: int) -> bool:
            if self._loop(t, a, i) is None:
                return True  # not running: nothing to reset
            if t == PidType.POSITION:
                a.hold()
            elif t == PidType.VELOCITY:
                a.keep_velocity()
            return True  # torque: the torque exerted is the reference already
        return t is not None and self._on_axis(j, reset) is True

    def isPidEnabled(self, pidtype: PidType, j: int) -> Optional[bool]:
        t = _loop_type(pidtype)
        return None if t is None else self._on_axis(j, lambda a, i: self._enabled[i][t])
