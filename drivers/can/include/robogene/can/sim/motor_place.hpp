// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Where a physical joint's motor sits on the simulated boards, by the name a user gives it: a joint of
// head.ini on an uncoupled board is its axis's motor; on a coupled board (the eyes) the joints of
// head.ini are version and vergence, which no one motor drives, so the motors are named as the
// coupling names them (left_eye_pan, right_eye_pan). What `robogene can-sim --backlash` and
// `--reverse-joint-encoder` address.
#pragma once

#include <string>

#include "robogene/can/head_config.hpp"

namespace robogene::can::sim {

struct MotorPlace {
  int board = 0;  // CAN address
  int motor = 0;  // 0 or 1, also its joint encoder's connector
};

// Throws robogene::Error naming `name` and the names that would do when it is neither.
MotorPlace motor_place(const HeadConfig& head, const std::string& name);

}  // namespace robogene::can::sim
