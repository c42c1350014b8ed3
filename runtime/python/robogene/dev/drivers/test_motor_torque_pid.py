# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""test_motor's torque control and PID controllers, as the C++ test_motor_torque_pid.cpp: a torque
reference drives its axis as a damped rigid body and switches it to torque mode; each axis keeps
the gains and the error limit of its four controllers; a loop's reference, error and output exist
only while its axis runs it (position: the target position, velocity: the commanded velocity,
torque: the torque reference; every loop's output is the torque the motor exerts)."""
from __future__ import annotations

import dataclasses
import math
from typing import List, Optional, Sequence, Tuple

from ..generated import ControlMode, Pid, PidType


def _finite(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def _pid_type(pidtype) -> Optional[PidType]:
    try:
        return PidType(pidtype)
    except ValueError:
        return None


def _finite_pid(pid) -> bool:
    return isinstance(pid, Pid) and all(_finite(getattr(pid, f.name)) for f in dataclasses.fields(Pid))


def _limit(v) -> bool:
    return _finite(v) and v >= 0


class TorqueAndPids:
    """Mixed into TestMotor, whose lock, axes, modes and helpers (_on_axis, _set_axis, _set_all,
    _read_all) it uses."""

    def _reset_pids(self, n: int) -> None:
        self._pids = [{t: Pid() for t in PidType} for _ in range(n)]
        self._error_limits = [{t: 0.0 for t in PidType} for _ in range(n)]

    # ---- ITorqueControl --------------------------------------------------------------------

    def _torque_ok(self, t) -> bool:
        return _finite(t) and abs(t) <= self._max_torque

    def _push(self, a, i: int, t) -> None:
        a.push(float(t))
        self._modes[i] = ControlMode.TORQUE

    def getTorque(self, j: int) -> Optional[float]:
        return self._on_axis(j, lambda a, i: a.torque())

    def getTorques(self) -> Optional[List[float]]:
        return self._read_all(lambda a, i: a.torque())

    def setRefTorque(self, j: int, t: float) -> bool:
        return self._set_axis(j, t, self._torque_ok, self._push)

    def setRefTorques(self, ts: Sequence[float]) -> bool:
        return self._set_all(ts, self._torque_ok, self._push)

    def getRefTorque(self, j: int) -> Optional[float]:
        return self._on_axis(j, lambda a, i: a.ref_torque)

    def getRefTorques(self) -> Optional[List[float]]:
        return self._read_all(lambda a, i: a.ref_torque)

    def getTorqueRange(self, j: int) -> Optional[Tuple[float, float]]:
        return self._on_axis(j, lambda a, i: (-self._max_torque, self._max_torque))

    def getTorqueRanges(self) -> Optional[Tuple[List[float], List[float]]]:
        mins = self._read_all(lambda a, i: -self._max_torque)
        maxs = self._read_all(lambda a, i: self._max_torque)
        return None if mins is None or maxs is None else (mins, maxs)

    # ---- IPidControl: gains and error limits -----------------------------------------------

    def setPid(self, pidtype: PidType, j: int, pid: Pid) -> bool:
        t = _pid_type(pidtype)
        if t is None or not _finite_pid(pid):
            return False
        return self._on_axis(j, lambda a, i: self._pids[i].__setitem__(t, dataclasses.replace(pid)) or True) is True

    def setPids(self, pidtype: PidType, pids: Sequence[Pid]) -> bool:
        t = _pid_type(pidtype)
        with self._lock:
            if t is None or not self._open or len(pids) != len(self._axes) or not all(map(_finite_pid, pids)):
                return False
            for i, pid in enumerate(pids):
                self._pids[i][t] = dataclasses.replace(pid)
            return True

    def getPid(self, pidtype: PidType, j: int) -> Optional[Pid]:
        t = _pid_type(pidtype)
        return None if t is None else self._on_axis(j, lambda a, i: dataclasses.replace(self._pids[i][t]))

    def getPids(self, pidtype: PidType) -> Optional[List[Pid]]:
        t = _pid_type(pidtype)
        return None if t is None else self._read_all(lambda a, i: dataclasses.replace(self._pids[i][t]))

    def setPidErrorLimit(self, pidtype: PidType, j: int, limit: float) -> bool:
        t = _pid_type(pidtype)
        if t is None or not _limit(limit):
            return False
        return self._on_axis(j, lambda a, i: self._error_limits[i].__setitem__(t, float(limit)) or True) is True

    def setPidErrorLimits(self, pidtype: PidType, limits: Sequence[float]) -> bool:
        t = _pid_type(pidtype)
        with self._lock:
            if t is None or not self._open or len(limits) != len(self._axes) or not all(map(_limit, limits)):
                return False
            for i, v in enumerate(limits):
                self._error_limits[i][t] = float(v)
            return True

    def getPidErrorLimit(self, pidtype: PidType, j: int) -> Optional[float]:
        t = _pid_type(pidtype)
        return None if t is None else self._on_axis(j, lambda a, i: self._error_limits[i][t])

    def getPidErrorLimits(self, pidtype: PidType) -> Optional[List[float]]:
        t = _pid_type(pidtype)
        return None if t is None else self._read_all(lambda a, i: self._error_limits[i][t])

    # ---- IPidControl: the loops ------------------------------------------------------------

    def _loop(self, pidtype, a, i: int) -> Optional[Tuple[float, float]]:
        """(reference, measured) of the loop if axis i runs it; with the lock held."""
        t, mode = _pid_type(pidtype), self._modes[i]
        if t == PidType.POSITION and mode == ControlMode.POSITION:
            return a.target, a.position
        if t == PidType.VELOCITY and mode == ControlMode.VELOCITY:
            return a.ref_velocity, a.velocity
        if t == PidType.TORQUE and mode == ControlMode.TORQUE:
            return a.ref_torque, a.torque()
        return None  # not running, or a current loop, which the model does not have

    def _per_axis(self, j: int, pidtype, f) -> Optional[float]:
        return self._on_axis(j, lambda a, i: None if self._loop(pidtype, a, i) is None else f(a, i))

    def _every_axis(self, pidtype, f) -> Optional[List[float]]:
        values = self._read_all(lambda a, i: None if self._loop(pidtype, a, i) is None else f(a, i))
        return None if values is None or any(v is None for v in values) else values

    def _reference(self, a, i: int, pidtype) -> float:
        return self._loop(pidtype, a, i)[0]

    def _error(self, a, i: int, pidtype) -> float:
        reference, measured = self._loop(pidtype, a, i)
        return reference - measured

    # Setting a loop's reference directly, bypassing the trajectories, is not simulated.
    def setPidReference(self, pidtype: PidType, j: int, ref: float) -> bool:
        return False

    def setPidReferences(self, pidtype: PidType, refs: Sequence[float]) -> bool:
        return False

    def getPidReference(self, pidtype: PidType, j: int) -> Optional[float]:
        return self._per_axis(j, pidtype, lambda a, i: self._reference(a, i, pidtype))

    def getPidReferences(self, pidtype: PidType) -> Optional[List[float]]:
        return self._every_axis(pidtype, lambda a, i: self._reference(a, i, pidtype))

    def getPidError(self, pidtype: PidType, j: int) -> Optional[float]:
        return self._per_axis(j, pidtype, lambda a, i: self._error(a, i, pidtype))

    def getPidErrors(self, pidtype: PidType) -> Optional[List[float]]:
        return self._every_axis(pidtype, lambda a, i: self._error(a, i, pidtype))

    def getPidOutput(self, pidtype: PidType, j: int) -> Optional[float]:
        return self._per_axis(j, pidtype, lambda a, i: a.torque())

    def getPidOutputs(self, pidtype: PidType) -> Optional[List[float]]:
        return self._every_axis(pidtype, lambda a, i: a.torque())
