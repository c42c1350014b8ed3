// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// One simulated two-motor board, answering the protocol as the firmware does: commands to its
// address (or to the broadcast address) change its axes or get a reply; every control period
// (1 ms) it runs a trajectory generator and a position PID per axis, drives its motor models with
// the PID's PWM, reads their encoders and queues the broadcasts its policy enables. On a coupled
// board (the eyes) the PID runs on the joints (version, vergence), its outputs are mixed to the
// two motors with j2m and the joints are read back from the motors with m2j, as the reference
// MC4 does in its firmware.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "motor_control.hpp"
#include "robogene/can/head_config.hpp"
#include "robogene/can/sim/dc_motor.hpp"

namespace robogene::can::sim {

class BoardSim {
 public:
  BoardSim(const HeadConfig& head, const BoardConfig& board, const MotorParameters& motor);

  int address() const { return address_; }
  // Handles a command addressed to this board; returns the reply when the command has one.
  std::optional<Envelope> handle(const Envelope& command);
  // Advances one control period of dt seconds ending at `now`; appends due broadcasts to `out`.
  void step(double now, double dt, std::vector<Envelope>& out);

  // For tests: the joint-side angle of motor m (degrees), and an axis's measured counts.
  double motor_degrees(int m) const { return motors_[static_cast<std::size_t>(m)].joint_degrees(); }
  std::int32_t measured_counts(int axis) const;
  ControlMode mode(int axis) const { return axes_[static_cast<std::size_t>(axis)].mode; }

 private:
  struct Axis {
    bool present = false;
    ControlMode mode = ControlMode::idle;
    double ref = 0.0, ref_velocity = 0.0;  // trajectory, counts and counts/s
    double target = 0.0, move_speed = 0.0, acceleration = 0.0;
    double velocity_command = 0.0, velocity_command_time = -1.0;
    bool done = true;
    double min = 0.0, max = 0.0, max_velocity = 0.0;
    PidGains pid;
    double integral = 0.0, last_error = 0.0;
    std::int16_t output = 0;
    double counts_per_degree = 1.0;
    double encoder_offset = 0.0;  // counts added by set_encoder_position
    double measured = 0.0, speed = 0.0, accel = 0.0;
  };

  void reply_to(const Envelope& command, Message m, std::optional<Envelope>& out) const;
  void set_mode(Axis& a, ControlMode mode);
  void run_trajectory(Axis& a, double now, double dt);
  std::int16_t run_pid(Axis& a);
  void read_encoders(double dt);
  void queue_broadcasts(double now, std::vector<Envelope>& out);
  bool due(double now, double period_ms, double& last) const;

  int address_;
  int protocol_major_, protocol_minor_;
  double pwm_full_scale_;
  double velocity_timeout_s_;
  std::uint32_t policy_ = 0;
  std::optional<Coupling> coupling_;
  std::array<Axis, 2> axes_{};
  std::array<DcMotor, 2> motors_;
  std::array<double, 2> joint_degrees_per_motor_degree_{{1.0, 1.0}};
  double now_ = 0.0;
  std::array<double, 6> last_sent_{{-1e9, -1e9, -1e9, -1e9, -1e9, -1e9}};
  StatusBroadcast last_status_{};
  bool status_sent_ = false;
};

}  // namespace robogene::can::sim
