# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""test_motor in Python: the same simulated control board as the C++ driver (see
drivers/fake/test_motor/test_motor.hpp and test_motor_torque_pid.cpp for the behaviour and the
configuration keys)."""
from __future__ import annotations

import copy
import math
import threading
from typing import Callable, List, Optional, Sequence

from ..device_driver import DeviceDriver, ISimulationClock, SimClock
from ..generated import (ControlMode, IControlMode, IEncoders, IPidControl, IPositionControl, ITorqueControl,
                         IVelocityControl)
from ..property import Property
from .axis_motion import POSITION, AxisMotion
from .test_motor_pid_switches import PidSwitches
from .test_motor_torque_pid import TorqueAndPids


def _finite(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def _positive(v) -> bool:
    return _finite(v) and v > 0


class TestMotor(TorqueAndPids, PidSwitches, DeviceDriver, IEncoders, IPositionControl, IVelocityControl, IControlMode,
                ITorqueControl, IPidControl, ISimulationClock):
    __test__ = False  # not a pytest test class, despite the name

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._clock = SimClock()
        self._last = 0.0
        self._open = False
        self._axes: List[AxisMotion] = []
        self._modes: List[ControlMode] = []
        self._max_torque = 5.0
        self._pids: List[dict] = []
        self._error_limits: List[dict] = []
        self._enabled: List[dict] = []

    # ---- DeviceDriver, ISimulationClock -----------------------------------------------------

    def open(self, config: Property) -> bool:
        with self._lock:
            n = config.get_int("axes", 4, 1, 64)
            speed = config.get_float("ref_speed", 10.0, 1e-9, 1e9)
            acc = config.get_float("ref_acceleration", 50.0, 1e-9, 1e9)
            max_torque = config.get_float("max_torque", 5.0, 1e-9, 1e9)
            inertia = config.get_float("inertia", 0.01, 1e-9, 1e9)
            damping = config.get_float("damping", 0.5, 1e-9, 1e9)
            self._clock.configure(config)
            self._axes = [AxisMotion(speed, acc) for _ in range(n)]
            for axis in self._axes:
                axis.inertia, axis.damping = inertia, damping
            self._max_torque = max_torque
            self._modes = [ControlMode.POSITION] * n
            self._reset_pids(n)
            self._reset_switches(n)
            self._last = self._clock.now()
            self._open = True
            return True

    def close(self) -> bool:
        with self._lock:
            self._open = False
            self._axes, self._modes = [], []
            self._reset_pids(0)
            self._reset_switches(0)
            return True

    def now(self) -> float:
        with self._lock:
            return self._clock.now()

    def advance(self, seconds: float) -> bool:
        with self._lock:
            if not self._open or not self._clock.advance(seconds):
                return False
            self._catch_up()
            return True

    def _catch_up(self) -> None:
        t = self._clock.now()
        if t > self._last:
            for axis in self._axes:
                axis.step(t - self._last)
            self._last = t

    def _on_axis(self, j, f: Callable[[AxisMotion, int], object]):
        with self._lock:
            if not self._open or isinstance(j, bool) or not isinstance(j, int) or not 0 <= j < len(self._axes):
                return None
            self._catch_up()
            return f(self._axes[j], j)

    def _set_axis(self, j, value, check, f) -> bool:
        if not check(value):
            return False

        def apply(a: AxisMotion, i: int) -> bool:
            axis, mode = copy.copy(a), self._modes[i]
            if f(a, i, value) is False:
                return False
            if not self._loop_allowed(i, self._modes[i]):  # it would run a disabled loop: undo
                self._axes[i], self._modes[i] = axis, mode
                return False
            return True
        return self._on_axis(j, apply) is True

    def _set_all(self, values: Sequence, check, f) -> bool:
        with self._lock:
            if not self._open or len(values) != len(self._axes) or not all(check(v) for v in values):
                return False
            self._catch_up()
            axes, modes = [copy.copy(a) for a in self._axes], list(self._modes)
            for i, v in enumerate(values):
                f(self._axes[i], i, v)
            if not all(self._loop_allowed(i, m) for i, m in enumerate(self._modes)):
                self._axes, self._modes = axes, modes  # one axis would run a disabled loop
                return False
            return True

    def _read_all(self, f) -> Optional[list]:
        with self._lock:
            if not self._open:
                return None
            self._catch_up()
            return [f(a, i) for i, a in enumerate(self._axes)]

    # ---- shared ----------------------------------------------------------------------------

    def getAxes(self) -> Optional[int]:
        with self._lock:
            return len(self._axes) if self._open else None

    def setRefAcceleration(self, j: int, acc: float) -> bool:
        return self._set_axis(j, acc, _positive, lambda a, i, v: setattr(a, "ref_acceleration", float(v)))

    def setRefAccelerations(self, accs: Sequence[float]) -> bool:
        return self._set_all(accs, _positive, lambda a, i, v: setattr(a, "ref_acceleration", float(v)))

    def getRefAcceleration(self, j: int) -> Optional[float]:
        return self._on_axis(j, lambda a, i: a.ref_acceleration)

    def getRefAccelerations(self) -> Optional[List[float]]:
        return self._read_all(lambda a, i: a.ref_acceleration)

    def stop(self, j: int) -> bool:
        return self._on_axis(j, lambda a, i: a.stop() or True) is True

    def stopAll(self) -> bool:
        return self._read_all(lambda a, i: a.stop()) is not None

    # ---- IEncoders -------------------------------------------------------------------------

    def getEncoder(self, j: int) -> Optional[float]:
        return self._on_axis(j, lambda a, i: a.position)

    def getEncoders(self) -> Optional[List[float]]:
        return self._read_all(lambda a, i: a.position)

    def getEncoderSpeed(self, j: int) -> Optional[float]:
        return self._on_axis(j, lambda a, i: a.velocity)

    def getEncoderSpeeds(self) -> Optional[List[float]]:
        return self._read_all(lambda a, i: a.velocity)

    def getEncoderAcceleration(self, j: int) -> Optional[float]:
        return self._on_axis(j, lambda a, i: a.acceleration)

    def getEncoderAccelerations(self) -> Optional[List[float]]:
        return self._read_all(lambda a, i: a.acceleration)

    def resetEncoder(self, j: int) -> bool:
        return self.setEncoder(j, 0.0)

    def resetEncoders(self) -> bool:
        return self._read_all(lambda a, i: a.set_position(0.0)) is not None

    def setEncoder(self, j: int, val: float) -> bool:
        return self._set_axis(j, val, _finite, lambda a, i, v: a.set_position(float(v)))

    def setEncoders(self, vals: Sequence[float]) -> bool:
        return self._set_all(vals, _finite, lambda a, i, v: a.set_position(float(v)))

    # ---- IPositionControl ------------------------------------------------------------------

    def _move(self, a: AxisMotion, i: int, target: float) -> None:
        a.move_to(float(target))
        self._modes[i] = ControlMode.POSITION

    def _relative(self, a: AxisMotion, i: int, delta: float) -> None:
        self._move(a, i, (a.target if a.goal == POSITION else a.position) + delta)

    def positionMove(self, j: int, ref: float) -> bool:
        return self._set_axis(j, ref, _finite, self._move)

    def positionMoveAll(self, refs: Sequence[float]) -> bool:
        return self._set_all(refs, _finite, self._move)

    def relativeMove(self, j: int, delta: float) -> bool:
        return self._set_axis(j, delta, _finite, self._relative)

    def relativeMoveAll(self, deltas: Sequence[float]) -> bool:
        return self._set_all(deltas, _finite, self._relative)

    def checkMotionDone(self, j: int) -> Optional[bool]:
        return self._on_axis(j, lambda a, i: a.done())

    def checkMotionDoneAll(self) -> Optional[List[bool]]:
        return self._read_all(lambda a, i: a.done())

    def setRefSpeed(self, j: int, sp: float) -> bool:
        return self._set_axis(j, sp, _positive, lambda a, i, v: setattr(a, "ref_speed", float(v)))

    def setRefSpeeds(self, sps: Sequence[float]) -> bool:
        return self._set_all(sps, _positive, lambda a, i, v: setattr(a, "ref_speed", float(v)))

    def getRefSpeed(self, j: int) -> Optional[float]:
        return self._on_axis(j, lambda a, i: a.ref_speed)

    def getRefSpeeds(self) -> Optional[List[float]]:
        return self._read_all(lambda a, i: a.ref_speed)

    def getTargetPosition(self, j: int) -> Optional[float]:
        return self._on_axis(j, lambda a, i: a.target)

    def getTargetPositions(self) -> Optional[List[float]]:
        return self._read_all(lambda a, i: a.target)

    # ---- IVelocityControl ------------------------------------------------------------------

    def _move_at(self, a: AxisMotion, i: int, v: float) -> None:
        a.move_at(float(v))
        self._modes[i] = ControlMode.VELOCITY

    def velocityMove(self, j: int, sp: float) -> bool:
        return self._set_axis(j, sp, _finite, self._move_at)

    def velocityMoveAll(self, sps: Sequence[float]) -> bool:
        return self._set_all(sps, _finite, self._move_at)

    def getRefVelocity(self, j: int) -> Optional[float]:
        return self._on_axis(j, lambda a, i: a.ref_velocity)

    def getRefVelocities(self) -> Optional[List[float]]:
        return self._read_all(lambda a, i: a.ref_velocity)

    # ---- IControlMode ----------------------------------------------------------------------

    _SIMULATED = (ControlMode.IDLE, ControlMode.POSITION, ControlMode.VELOCITY, ControlMode.TORQUE)

    def _apply_mode(self, a: AxisMotion, i: int, mode) -> None:
        mode = ControlMode(mode)
        if mode == ControlMode.IDLE:
            a.idle()
        elif mode == ControlMode.POSITION and self._modes[i] != mode:
            a.move_to(a.position)  # brake at the reference acceleration, hold where it rests
            a.stop()
        elif mode == ControlMode.VELOCITY and self._modes[i] != mode:
            a.move_at(0.0)
        elif mode == ControlMode.TORQUE and self._modes[i] != mode:
            a.push(0.0)  # no torque until one is asked for
        self._modes[i] = mode

    def getControlMode(self, j: int) -> Optional[ControlMode]:
        return self._on_axis(j, lambda a, i: self._modes[i])

    def getControlModes(self) -> Optional[List[ControlMode]]:
        return self._read_all(lambda a, i: self._modes[i])

    def setControlMode(self, j: int, mode: ControlMode) -> bool:
        return self._set_axis(j, mode, lambda m: m in self._SIMULATED, self._apply_mode)

    def setControlModes(self, modes: Sequence[ControlMode]) -> bool:
        return self._set_all(modes, lambda m: m in self._SIMULATED, self._apply_mode)
