// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/sim/board_sim.hpp"

#include <cmath>
#include <type_traits>

namespace robogene::can::sim {
namespace {

constexpr std::uint8_t kFirmwareVersion = 1, kFirmwareRevision = 0, kFirmwareBuild = 0;

std::int32_t to_counts(double v) {
  return static_cast<std::int32_t>(std::clamp(std::round(v), -2147483647.0, 2147483647.0));
}

// Speeds and accelerations must fit their int16 fields (10 count/s and 1000 count/s^2 steps).
double fit_speed(double v) { return std::clamp(v, -327670.0, 327670.0); }
double fit_acceleration(double v) { return std::clamp(v, -32767000.0, 32767000.0); }

}  // namespace

BoardSim::BoardSim(const HeadConfig& head, const BoardConfig& board, const MotorParameters& motor)
    : address_(board.address),
      protocol_major_(head.protocol_major),
      protocol_minor_(head.protocol_minor),
      pwm_full_scale_(head.pwm_full_scale),
      velocity_timeout_s_(head.velocity_timeout_ms / 1000.0),
      policy_(0),
      coupling_(board.coupling) {
  for (std::size_t i = 0; i < 2; ++i) {
    MotorParameters p = motor;
    const int j = board.joints[i];
    if (j < 0) {
      motors_[i] = DcMotor(p);
      continue;
    }
    const JointConfig& jc = head.joints[static_cast<std::size_t>(j)];
    p.gear_ratio = jc.gear_ratio;
    p.current_limit = jc.current_limit / 1000.0;
    motors_[i] = DcMotor(p);
    Axis& a = axes_[i];
    a.present = true;
    a.counts_per_degree = jc.counts_per_degree;
    a.min = jc.min * jc.counts_per_degree;
    a.max = jc.max * jc.counts_per_degree;
    a.max_velocity = jc.max_velocity * jc.counts_per_degree;
    a.acceleration = 4.0 * a.max_velocity;
    a.pid = jc.pid;
  }
  read_encoders(0.0);
  for (auto& a : axes_) a.ref = a.target = a.measured;
}

std::int32_t BoardSim::measured_counts(int axis) const {
  return to_counts(axes_[static_cast<std::size_t>(axis)].measured);
}

void BoardSim::reply_to(const Envelope& command, Message m, std::optional<Envelope>& out) const {
  out = Envelope{static_cast<std::uint8_t>(address_), command.source, command.axis, std::move(m)};
}

void BoardSim::set_mode(Axis& a, ControlMode mode) {
  if (mode == ControlMode::force_idle) mode = ControlMode::idle;
  if (mode != ControlMode::idle && mode != ControlMode::position && mode != ControlMode::velocity) {
    return;  // modes this board does not implement leave the axis as it was
  }
  if (a.mode == mode) {
    return;  // already there: keep the move in progress
  }
  a.ref = a.target = a.measured;
  a.ref_velocity = a.velocity_command = 0.0;
  a.integral = 0.0;
  a.last_error = 0.0;
  a.output = 0;
  a.done = true;
  a.mode = mode;
}

std::optional<Envelope> BoardSim::handle(const Envelope& command) {
  std::optional<Envelope> out;
  Axis& a = axes_[command.axis & 1U];
  if (!a.present) return out;
  std::visit(
      [&](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, GetControlMode>) {
          reply_to(command, GetControlModeReply{a.mode}, out);
        } else if constexpr (std::is_same_v<M, SetControlMode>) {
          set_mode(a, m.mode);
        } else if constexpr (std::is_same_v<M, MotionDone>) {
          reply_to(command, MotionDoneReply{a.done}, out);
        } else if constexpr (std::is_same_v<M, GetEncoderPosition>) {
          reply_to(command, GetEncoderPositionReply{to_counts(a.measured), std::round(fit_speed(a.speed) / 10) * 10}, out);
        } else if constexpr (std::is_same_v<M, GetDesiredPosition>) {
          reply_to(command, GetDesiredPositionReply{to_counts(a.target)}, out);
        } else if constexpr (std::is_same_v<M, SetDesiredAcceleration>) {
          if (m.acceleration > 0) a.acceleration = m.acceleration;
        } else if constexpr (std::is_same_v<M, GetDesiredAcceleration>) {
          reply_to(command, GetDesiredAccelerationReply{std::round(fit_acceleration(a.acceleration) / 1000) * 1000}, out);
        } else if constexpr (std::is_same_v<M, PositionMove>) {
          if (a.mode != ControlMode::position) return;  // as the firmware: only in position mode
          a.target = std::clamp(static_cast<double>(m.position), a.min, a.max);
          a.move_speed = std::clamp(std::fabs(m.speed), 10.0, a.max_velocity);
          a.done = false;
        } else if constexpr (std::is_same_v<M, VelocityMove>) {
          if (a.mode != ControlMode::velocity) return;
          a.velocity_command = std::clamp(m.speed, -a.max_velocity, a.max_velocity);
          if (m.acceleration > 0) a.acceleration = m.acceleration;
          a.velocity_command_time = now_;
        } else if constexpr (std::is_same_v<M, SetEncoderPosition>) {
          const double shift = m.position - a.measured;
          a.encoder_offset += shift;
          a.measured += shift;
          a.ref += shift;
          a.target += shift;
        } else if constexpr (std::is_same_v<M, StopTrajectory>) {
          a.target = a.ref;
          a.velocity_command = 0.0;
        } else if constexpr (std::is_same_v<M, SetBoardId>) {
          if (m.address >= 1 && m.address <= 14) address_ = m.address;
        } else if constexpr (std::is_same_v<M, GetBoardId>) {
          reply_to(command, GetBoardIdReply{static_cast<std::uint8_t>(address_)}, out);
        } else if constexpr (std::is_same_v<M, GetPidOutput>) {
          reply_to(command, GetPidOutputReply{a.output}, out);
        } else if constexpr (std::is_same_v<M, SetMinPosition>) {
          a.min = m.position;
        } else if constexpr (std::is_same_v<M, GetMinPosition>) {
          reply_to(command, GetMinPositionReply{to_counts(a.min)}, out);
        } else if constexpr (std::is_same_v<M, SetMaxPosition>) {
          a.max = m.position;
        } else if constexpr (std::is_same_v<M, GetMaxPosition>) {
          reply_to(command, GetMaxPositionReply{to_counts(a.max)}, out);
        } else if constexpr (std::is_same_v<M, SetMaxVelocity>) {
          if (m.speed > 0) a.max_velocity = m.speed;
        } else if constexpr (std::is_same_v<M, GetMaxVelocity>) {
          reply_to(command, GetMaxVelocityReply{std::round(fit_speed(a.max_velocity) / 10) * 10}, out);
        } else if constexpr (std::is_same_v<M, SetCurrentLimit>) {
          if (m.current > 0) motors_[command.axis & 1U].set_current_limit(m.current / 1000.0);
        } else if constexpr (std::is_same_v<M, SetBroadcastPolicy>) {
          policy_ = m.mask;
        } else if constexpr (std::is_same_v<M, SetPositionPid>) {
          a.pid.kp = m.kp;
          a.pid.ki = m.ki;
          a.pid.kd = m.kd;
          a.pid.shift = std::min<int>(m.shift, 15);
        } else if constexpr (std::is_same_v<M, GetPositionPid>) {
          reply_to(command, GetPositionPidReply{static_cast<std::int16_t>(a.pid.kp), static_cast<std::int16_t>(a.pid.ki),
                                                static_cast<std::int16_t>(a.pid.kd), static_cast<std::uint8_t>(a.pid.shift)},
                   out);
        } else if constexpr (std::is_same_v<M, SetPositionPidLimits>) {
          a.pid.offset = m.offset;
          a.pid.output_limit = m.output_limit;
          a.pid.integral_limit = m.integral_limit;
        } else if constexpr (std::is_same_v<M, GetPositionPidLimits>) {
          reply_to(command, GetPositionPidLimitsReply{static_cast<std::int16_t>(a.pid.offset),
                                                      static_cast<std::int16_t>(a.pid.output_limit),
                                                      static_cast<std::int16_t>(a.pid.integral_limit)},
                   out);
        } else if constexpr (std::is_same_v<M, SetVelocityTimeout>) {
          if (m.timeout > 0) velocity_timeout_s_ = m.timeout / 1000.0;
        } else if constexpr (std::is_same_v<M, GetFirmwareVersion>) {
          GetFirmwareVersionReply r;
          r.board_type = BoardType::robogene_motor_board;
          r.firmware_version = kFirmwareVersion;
          r.firmware_revision = kFirmwareRevision;
          r.firmware_build = kFirmwareBuild;
          r.protocol_major = static_cast<std::uint8_t>(protocol_major_);
          r.protocol_minor = static_cast<std::uint8_t>(protocol_minor_);
          r.compatible = m.protocol_major == protocol_major_ && m.protocol_minor <= protocol_minor_;
          reply_to(command, r, out);
        }
        // Replies and broadcasts from other nodes are not commands: a board ignores them.
      },
      command.message);
  return out;
}

void BoardSim::run_trajectory(Axis& a, double now, double dt) {
  const double acc = std::max(a.acceleration, 1.0);
  auto approach = [&](double wanted) {
    const double dv = std::clamp(wanted - a.ref_velocity, -acc * dt, acc * dt);
    a.ref_velocity += dv;
  };
  if (a.mode == ControlMode::position) {
    const double distance = a.target - a.ref;
    if (std::fabs(distance) < 0.5 && std::fabs(a.ref_velocity) <= acc * dt) {
      a.ref = a.target;
      a.ref_velocity = 0.0;
      a.done = true;
      return;
    }
    // Trapezoidal profile: cruise at the move's speed, brake in time to stop on the target.
    const double braking = std::sqrt(2.0 * acc * std::fabs(distance));
    approach(std::copysign(std::min(a.move_speed, braking), distance));
    const double step = a.ref_velocity * dt;
    a.ref = std::fabs(step) >= std::fabs(distance) && (step > 0) == (distance > 0) ? a.target : a.ref + step;
  } else if (a.mode == ControlMode::velocity) {
    if (a.velocity_command != 0.0 && now - a.velocity_command_time > velocity_timeout_s_) {
      a.velocity_command = 0.0;  // the host went quiet: stop, as the firmware's velocity timeout does
    }
    approach(a.velocity_command);
    a.ref += a.ref_velocity * dt;
    if (a.ref < a.min || a.ref > a.max) {
      a.ref = std::clamp(a.ref, a.min, a.max);
      a.ref_velocity = 0.0;
    }
    a.target = a.ref;
  }
}

std::int16_t BoardSim::run_pid(Axis& a) {
  if (a.mode == ControlMode::idle) {
    a.ref = a.target = a.measured;
    a.integral = 0.0;
    return 0;
  }
  const double error = a.ref - a.measured;
  const double scale = std::ldexp(1.0, a.pid.shift);
  const double integral_cap = a.pid.integral_limit * scale;
  a.integral = std::clamp(a.integral + a.pid.ki * error, -integral_cap, integral_cap);
  const double derivative = error - a.last_error;
  a.last_error = error;
  const double out = (a.pid.kp * error + a.integral + a.pid.kd * derivative) / scale + a.pid.offset;
  return static_cast<std::int16_t>(std::clamp(std::round(out), -double(a.pid.output_limit), double(a.pid.output_limit)));
}

void BoardSim::read_encoders(double dt) {
  std::array<double, 2> joint_degrees{};
  if (coupling_) {
    for (std::size_t r = 0; r < 2; ++r) {
      joint_degrees[r] = coupling_->m2j[r][0] * motors_[0].joint_degrees() + coupling_->m2j[r][1] * motors_[1].joint_degrees();
    }
  } else {
    for (std::size_t i = 0; i < 2; ++i) joint_degrees[i] = motors_[i].joint_degrees();
  }
  for (std::size_t i = 0; i < 2; ++i) {
    Axis& a = axes_[i];
    const double counts = std::round(joint_degrees[i] * a.counts_per_degree) + a.encoder_offset;
    if (dt > 0.0) {
      // Low-pass filtered differences (10 ms), as a board estimates speed from counts.
      constexpr double kAlpha = 0.1;
      const double speed = (counts - a.measured) / dt;
      const double previous = a.speed;
      a.speed += kAlpha * (speed - a.speed);
      a.accel += kAlpha * ((a.speed - previous) / dt - a.accel);
    }
    a.measured = counts;
  }
}

bool BoardSim::due(double now, double period_ms, double& last) const {
  if (now - last < period_ms / 1000.0 - 1e-9) return false;
  last = now;
  return true;
}

void BoardSim::queue_broadcasts(double now, std::vector<Envelope>& out) {
  const auto self = static_cast<std::uint8_t>(address_);
  if ((policy_ & broadcast_mask::position) && due(now, PositionBroadcast::period_ms, last_sent_[0])) {
    out.push_back(broadcast(self, PositionBroadcast{to_counts(axes_[0].measured), to_counts(axes_[1].measured)}));
  }
  if ((policy_ & broadcast_mask::pid_output) && due(now, PidOutputBroadcast::period_ms, last_sent_[1])) {
    out.push_back(broadcast(self, PidOutputBroadcast{axes_[0].output, axes_[1].output}));
  }
  if (policy_ & broadcast_mask::status) {
    StatusBroadcast s;
    s.mode0 = axes_[0].mode;
    s.mode1 = axes_[1].mode;
    const bool changed = !status_sent_ || !(s == last_status_);
    if (changed || due(now, StatusBroadcast::period_ms, last_sent_[2])) {
      last_sent_[2] = now;
      last_status_ = s;
      status_sent_ = true;
      out.push_back(broadcast(self, s));
    }
  }
  if ((policy_ & broadcast_mask::current) && due(now, CurrentBroadcast::period_ms, last_sent_[3])) {
    auto ma = [](double amps) { return static_cast<std::int16_t>(std::clamp(std::round(amps * 1000), -32768.0, 32767.0)); };
    out.push_back(broadcast(self, CurrentBroadcast{ma(motors_[0].current_amps()), ma(motors_[1].current_amps())}));
  }
  if ((policy_ & broadcast_mask::velocity) && due(now, VelocityBroadcast::period_ms, last_sent_[4])) {
    auto speed = [](double v) { return std::round(fit_speed(v) / 10) * 10; };
    auto accel = [](double v) { return std::round(fit_acceleration(v) / 1000) * 1000; };
    out.push_back(broadcast(self, VelocityBroadcast{speed(axes_[0].speed), accel(axes_[0].accel), speed(axes_[1].speed),
                                                    accel(axes_[1].accel)}));
  }
  if ((policy_ & broadcast_mask::supply) && due(now, SupplyBroadcast::period_ms, last_sent_[5])) {
    out.push_back(broadcast(self, SupplyBroadcast{12.0}));
  }
}

void BoardSim::step(double now, double dt, std::vector<Envelope>& out) {
  now_ = now;
  std::array<double, 2> outputs{};
  for (std::size_t i = 0; i < 2; ++i) {
    Axis& a = axes_[i];
    if (!a.present) continue;
    run_trajectory(a, now, dt);
    a.output = run_pid(a);
    outputs[i] = a.output;
  }
  for (std::size_t m = 0; m < 2; ++m) {
    const double pwm = coupling_ ? coupling_->j2m[m][0] * outputs[0] + coupling_->j2m[m][1] * outputs[1] : outputs[m];
    motors_[m].step(pwm / pwm_full_scale_, dt);
  }
  read_encoders(dt);
  queue_broadcasts(now, out);
}

}  // namespace robogene::can::sim
