# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The simulated motion of one axis, the same model as the C++ test_motor (axis_motion.cpp):
the time-optimal way to a target position or velocity within the reference speed and
acceleration, integrated in steps of at most one millisecond; under a torque reference a rigid
body with inertia and viscous damping, J dw/dt = t - b w, integrated exactly."""
from __future__ import annotations

import math

MAX_STEP = 1e-3
DEG_PER_RAD = 57.29577951308232  # 180 / pi
IDLE, POSITION, VELOCITY, TORQUE = "idle", "position", "velocity", "torque"


class AxisMotion:
    def __init__(self, ref_speed: float = 10.0, ref_acceleration: float = 50.0):
        self.goal = POSITION
        self.position = 0.0
        self.velocity = 0.0
        self.acceleration = 0.0
        self.target = 0.0
        self.ref_speed = ref_speed
        self.ref_acceleration = ref_acceleration
        self.ref_velocity = 0.0
        self.ref_torque = 0.0
        self.inertia = 0.01  # kg m^2
        self.damping = 0.5   # N m s/rad

    def step(self, dt: float) -> None:
        while dt > 0.0:
            h = min(dt, MAX_STEP)
            self._substep(h)
            dt -= h

    def _torque_substep(self, h: float) -> None:
        # J dw/dt = t - b w has w(h) = w_end + (w0 - w_end) e^(-h b/J), w_end = t / b; degrees.
        k = self.damping / self.inertia
        w_end = DEG_PER_RAD * self.ref_torque / self.damping
        decay = math.exp(-k * h)
        w0 = self.velocity
        self.velocity = w_end + (w0 - w_end) * decay
        self.position += w_end * h + (w0 - w_end) * (1.0 - decay) / k
        self.acceleration = DEG_PER_RAD * self.ref_torque / self.inertia - k * self.velocity

    def _substep(self, h: float) -> None:
        if self.goal == IDLE:
            return
        if self.goal == TORQUE:
            self._torque_substep(h)
            return
        a = self.ref_acceleration
        wanted = self.ref_velocity
        error = self.target - self.position
        if self.goal == POSITION:
            if error == 0.0 and self.velocity == 0.0:
                self.acceleration = 0.0
                return
            # Fastest end-of-step speed from which braking at `a` still stops at the target.
            v0 = math.copysign(1.0, error) * self.velocity
            left = abs(error) - 0.5 * v0 * h
            braking = 0.5 * (-a * h + math.sqrt(a * a * h * h + 8.0 * a * left)) if left > 0 else 0.0
            wanted = math.copysign(min(self.ref_speed, braking), error)
        dv = max(-a * h, min(a * h, wanted - self.velocity))
        v0 = self.velocity
        self.velocity += dv
        self.acceleration = dv / h
        self.position += 0.5 * (v0 + self.velocity) * h
        if self.goal == POSITION:
            after = self.target - self.position
            crossed = after == 0.0 or math.copysign(1.0, after) != math.copysign(1.0, error)
            if crossed and abs(self.velocity) <= 2.0 * a * h:
                self.position = self.target
                self.velocity = 0.0

    def move_to(self, target: float) -> None:
        self.goal, self.target = POSITION, target

    def move_at(self, velocity: float) -> None:
        self.goal, self.ref_velocity = VELOCITY, velocity

    def push(self, torque: float) -> None:
        self.goal, self.ref_torque = TORQUE, torque

    def idle(self) -> None:
        self.goal, self.velocity, self.acceleration = IDLE, 0.0, 0.0

    def hold(self) -> None:
        """A reset position loop: the present position becomes the target, held from standstill."""
        self.goal, self.target, self.velocity, self.acceleration = POSITION, self.position, 0.0, 0.0

    def keep_velocity(self) -> None:
        """A reset velocity loop: the present velocity becomes the commanded one, with no more ramp."""
        self.goal, self.ref_velocity, self.acceleration = VELOCITY, self.velocity, 0.0

    def stop(self) -> None:
        if self.goal == POSITION:
            self.target = self.position + self.velocity * abs(self.velocity) / (2.0 * self.ref_acceleration)
        elif self.goal == VELOCITY:
            self.ref_velocity = 0.0
        elif self.goal == TORQUE:
            self.ref_torque = 0.0  # the damping brings the axis to rest

    def torque(self) -> float:
        """The torque the motor exerts, N m: the reference under torque control, otherwise what
        the body needs for its present motion, J a + b w."""
        if self.goal == TORQUE:
            return self.ref_torque
        return (self.inertia * self.acceleration + self.damping * self.velocity) / DEG_PER_RAD

    def set_position(self, p: float) -> None:
        self.target += p - self.position
        self.position = p

    def done(self) -> bool:
        if self.velocity != 0.0:
            return False
        return self.goal != POSITION or self.position == self.target
