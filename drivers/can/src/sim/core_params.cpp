// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "core_params.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "robogene/error.hpp"

namespace robogene::can::sim {
namespace {

std::int16_t fit_i16(int v, const std::string& what) {
  if (v < -32768 || v > 32767) throw Error("simulated board: " + what + " " + std::to_string(v) + " does not fit int16");
  return static_cast<std::int16_t>(v);
}

// The core's axis parameters from a joint of head.ini, in counts as the firmware's table has them.
rg_axis_params_t axis_params(const JointConfig& jc) {
  rg_axis_params_t p{};
  p.present = true;
  p.min_position = static_cast<std::int32_t>(std::lround(jc.min * jc.counts_per_degree));
  p.max_position = static_cast<std::int32_t>(std::lround(jc.max * jc.counts_per_degree));
  p.max_speed = static_cast<std::int32_t>(std::lround(jc.max_velocity * jc.counts_per_degree));
  p.current_limit_ma = static_cast<std::int32_t>(std::lround(jc.current_limit));
  p.has_brake = jc.has_brake;
  p.counts_per_degree = static_cast<float>(jc.counts_per_degree);
  p.joint_encoder_bits = static_cast<std::uint8_t>(jc.joint_encoder_bits);
  p.joint_correction_limit = static_cast<std::int32_t>(std::lround(jc.joint_correction_limit * jc.counts_per_degree));
  p.pid.kp = fit_i16(jc.pid.kp, jc.name + " kp");
  p.pid.ki = fit_i16(jc.pid.ki, jc.name + " ki");
  p.pid.kd = fit_i16(jc.pid.kd, jc.name + " kd");
  p.pid.shift = static_cast<std::uint8_t>(std::clamp(jc.pid.shift, 0, 15));
  p.pid.offset = fit_i16(jc.pid.offset, jc.name + " offset");
  p.pid.output_limit = fit_i16(jc.pid.output_limit, jc.name + " output_limit");
  p.pid.integral_limit = fit_i16(jc.pid.integral_limit, jc.name + " integral_limit");
  const HomingConfig& h = jc.homing;
  p.homing.direction = static_cast<std::int8_t>(h.direction);
  p.homing.speed = static_cast<float>(std::lround(h.speed * jc.counts_per_degree));  // whole counts/s, as the table
  p.homing.pwm_limit = fit_i16(h.pwm, jc.name + " homing pwm");
  p.homing.stop_position = static_cast<std::int32_t>(std::lround(h.stop * jc.counts_per_degree));
  p.homing.backoff = static_cast<std::int32_t>(std::lround(h.backoff * jc.counts_per_degree));
  p.homing.timeout_ms = static_cast<std::uint32_t>(std::lround(h.timeout * 1000.0));
  p.homing.current_limit_ma = h.current;
  return p;
}

}  // namespace

double motor_counts_per_degree(const HeadConfig& head, const BoardConfig& board, std::size_t m) {
  const int j = board.joints[m];
  if (j < 0) return 1.0;
  const JointConfig& jc = head.joints[static_cast<std::size_t>(j)];
  // Uncoupled, the axis is the motor: its wire counts are the motor's. On the eye board each motor
  // counts 4 x lines x reduction per turn of its eye.
  return board.coupling ? 4.0 * jc.motor_encoder_lines * jc.gear_ratio / 360.0 : jc.counts_per_degree;
}

rg_board_params_t core_params(const HeadConfig& head, const BoardConfig& board) {
  rg_board_params_t p{};
  p.address = static_cast<std::uint8_t>(board.address);
  p.board_id = static_cast<std::uint8_t>(board.address);  // the head table's address: what its image is built for
  p.pwm_full_scale = static_cast<std::uint16_t>(head.pwm_full_scale);
  p.control_period_us = static_cast<std::uint32_t>(head.control_period_us);
  p.velocity_timeout_ms = static_cast<std::uint16_t>(head.velocity_timeout_ms);
  p.protocol_major = static_cast<std::uint8_t>(head.protocol_major);
  p.protocol_minor = static_cast<std::uint8_t>(head.protocol_minor);
  p.broadcast_policy = head.broadcast_policy;
  p.counts_m2a[0][0] = p.counts_m2a[1][1] = 1;
  for (std::size_t i = 0; i < 2; ++i) {
    const int j = board.joints[i];
    if (j >= 0) p.axes[i] = axis_params(head.joints[static_cast<std::size_t>(j)]);
  }
  if (board.coupling) {
    const Coupling& c = *board.coupling;
    // The firmware mixes version and vergence as left = version + vergence / 2, right = version -
    // vergence / 2; a configuration asking for another mix cannot run on it.
    const bool mix_ok = c.type == "version_vergence" && c.j2m[0][0] == 1.0 && c.j2m[0][1] == 0.5 &&
                        c.j2m[1][0] == 1.0 && c.j2m[1][1] == -0.5;
    if (!mix_ok) throw Error("simulated board '" + board.name + "': the firmware implements no coupling '" + c.type + "' with this j2m");
    p.coupling = RG_COUPLING_VERSION_VERGENCE;
    // axis counts = diag(axis counts/deg) m2j diag(deg/motor count): whole numbers on a coupling
    // the firmware can run.
    for (std::size_t r = 0; r < 2; ++r) {
      const double cpd = head.joints[static_cast<std::size_t>(board.joints[r])].counts_per_degree;
      for (std::size_t m = 0; m < 2; ++m) {
        const double v = cpd * c.m2j[r][m] / motor_counts_per_degree(head, board, m);
        if (std::fabs(v - std::round(v)) > 1e-6) {
          throw Error("simulated board '" + board.name + "': coupling counts are not whole (" + std::to_string(v) + ")");
        }
        p.counts_m2a[r][m] = static_cast<std::int8_t>(std::lround(v));
      }
    }
  }
  return p;
}

}  // namespace robogene::can::sim
