// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The simulated motion of one axis: the time-optimal way to reach a target position (or a target
// velocity) without exceeding the reference speed and acceleration, integrated in steps of at
// most one millisecond.
#pragma once

namespace robogene::dev {

class AxisMotion {
 public:
  enum class Goal { Idle, Position, Velocity };

  void step(double dt);

  // Commands; the caller has checked the values are finite (and positive for the references).
  void move_to(double target) { goal_ = Goal::Position; target_ = target; }
  void move_at(double velocity) { goal_ = Goal::Velocity; ref_velocity_ = velocity; }
  void idle() { goal_ = Goal::Idle; velocity_ = 0.0; acceleration_ = 0.0; }
  void stop();
  void set_ref_speed(double v) { ref_speed_ = v; }
  void set_ref_acceleration(double a) { ref_acceleration_ = a; }
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
  bool done() const;

 private:
  void substep(double h);

  Goal goal_ = Goal::Position;
  double position_ = 0.0;
  double velocity_ = 0.0;
  double acceleration_ = 0.0;
  double target_ = 0.0;
  double ref_speed_ = 10.0;
  double ref_acceleration_ = 50.0;
  double ref_velocity_ = 0.0;
};

}  // namespace robogene::dev
