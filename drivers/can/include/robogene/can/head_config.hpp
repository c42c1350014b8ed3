// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The head's board configuration (drivers/can/generated/head.ini, generated from the head parameter
// file), read and checked once for the driver and the simulator. A wrong or missing field throws
// dev::ConfigError naming the file, line, group and key ("head.ini:31: [GENERAL] key 'axis': ...").
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "robogene/dev/property.hpp"

namespace robogene::can {

// Position PID in board units: output = (kp e + ki sum(e) + kd de) >> shift, e in counts.
struct PidGains {
  int kp = 0, ki = 0, kd = 0, shift = 0;
  int offset = 0, output_limit = 0, integral_limit = 0;
};

// Homing against a hard stop ([HOMING]). direction 0: the joint does not home itself; on the eye
// board vergence is found when version homes, and `stop` is the vergence read there.
struct HomingConfig {
  int direction = 0;        // +1 towards the upper stop, -1 the lower
  double stop = 0;          // degrees, the joint's angle at the stop
  double speed = 0;         // deg/s
  int pwm = 0;              // PWM steps
  double backoff = 0;       // degrees
  double timeout = 0;       // s
  int current = 0;          // mA per motor while it seeks the stop (the run limit applies otherwise)
};

struct JointConfig {
  std::string name;
  int board = 0;                  // CAN address
  int axis = 0;                   // 0 or 1 on that board
  double counts_per_degree = 0;   // on the wire
  double gear_ratio = 0;          // motor turns per joint turn
  int motor_encoder_lines = 0;
  double min = 0, max = 0;        // degrees
  double max_velocity = 0;        // deg/s
  double current_limit = 0;       // mA
  bool has_brake = false;         // its motor has a power-off holding brake on the board's brake output
  int joint_encoder_bits = 0;     // its absolute joint encoder's bits (0: none): the board homes it from it
  // > 0: its board closes its position on the joint encoder, correcting the motor loop by at most this (deg at the
  // joint) before it stops it with joint_encoder_mismatch; 0: its position is its motor encoder's
  double joint_correction_limit = 0;
  PidGains pid;
  HomingConfig homing;
};

// Two joints driven by two motors together: motors = j2m * joints, joints = m2j * motors (deg).
struct Coupling {
  std::string type;
  std::array<int, 2> joints{};
  std::array<std::string, 2> motors;
  std::array<std::array<double, 2>, 2> j2m{}, m2j{};
};

struct BoardConfig {
  std::string name;
  int address = 0;
  std::array<int, 2> joints{{-1, -1}};  // joint index on axis 0 and 1 (-1: none)
  std::optional<Coupling> coupling;
};

struct HeadConfig {
  std::string source;             // the file, for messages
  std::string device;             // [CAN] device (socketcan interface name)
  int host_address = 0;
  std::uint32_t broadcast_policy = 0;
  int protocol_major = 0, protocol_minor = 0;
  int polling_interval_ms = 10, reply_timeout_ms = 500, velocity_timeout_ms = 100;
  int pwm_full_scale = 0;
  int control_period_us = 1000;
  std::vector<BoardConfig> boards;
  std::vector<JointConfig> joints;

  const BoardConfig* board(int address) const;
};

// Throws dev::ConfigError naming the field on anything missing, malformed or inconsistent
// (lists of the wrong length, an axis used twice, a board not on the bus, min >= max, a coupling
// whose matrices are not inverse, a protocol fingerprint other than the codec's).
HeadConfig read_head_config(const dev::Searchable& config);

}  // namespace robogene::can
