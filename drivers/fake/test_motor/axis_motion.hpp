// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The simulated motion of one axis: the time-optimal way to reach a target position (or a target
// velocity) without exceeding the reference speed and acceleration, integrated in steps of at
// most one millisecond. Under a torque reference the axis is a rigid body with inertia and
// viscous damping, J dw/dt = t - b w, integrated exactly.
#pragma once

namespace robogene::dev {

class AxisMotion {
 public:
  enum class Goal { Idle, Position, Velocity, Torque };

  void step(double dt);

  // Commands; the caller has checked the values are finite (and positive for the references).
  void move_to(double target) { goal_ = Goal::Position; target_ = target; }
  void move_at(double velocity) { goal_ = Goal::Velocity; ref_velocity_ = velocity; }
  void push(double torque) { goal_ = Goal::Torque; ref_torque_ = torque; }
  void idle() { goal_ = Goal::Idle; velocity_ = 0.0; acceleration_ = 0.0; }
  // A reset position loop: the present position becomes the target, held from standstill.
  void hold() { goal_ = Goal::Position; target_ = position_; velocity_ = 0.0; acceleration_ = 0.0; }
  // A reset velocity loop: the present velocity becomes the commanded one, with no more ramp.
  void keep_velocity() { goal_ = Goal::Velocity; ref_velocity_ = velocity_; acceleration_ = 0.0; }
  void stop();
  void set_ref_speed(double v) { ref_speed_ = v; }
  void set_ref_acceleration(double a) { ref_acceleration_ = a; }
  // The body driven by torque: inertia J in kg m^2 and viscous damping b in N m s/rad, both > 0.
  void set_dynamics(double inertia, double damping) { inertia_ = inertia; damping_ = damping; }
  // Re-labels the current position (encoder reset) without moving; a target moves along.
  void set_position(double p);

  Goal goal() const { return goal_; }
  double position() const { return position_; }
  double velocity() const { return velocity_; }
  double acceleration() const { return acceleration_; }
  double target() const { return target_; }
  double ref_speed() const { return ref_speed_; }
  double ref_acceleration() const { return ref_acceleration_; }
  double ref_velocity() const { return ref_velocity_; }
  double ref_torque() const { return ref_torque_; }
  // The torque the motor exerts, N m: the reference under torque control, otherwise what the
  // body needs for its present motion, J a + b w (zero when idle or at rest).
  double torque() const;
  bool done() const;

 private:
  void substep(double h);
  void torque_substep(double h);

  Goal goal_ = Goal::Position;
  double position_ = 0.0;
  double velocity_ = 0.0;
  double acceleration_ = 0.0;
  double target_ = 0.0;
  double ref_speed_ = 10.0;
  double ref_acceleration_ = 50.0;
  double ref_velocity_ = 0.0;
  double ref_torque_ = 0.0;
  double inertia_ = 0.01;
  double damping_ = 0.5;
};

}  // namespace robogene::dev
