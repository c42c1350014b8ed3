// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Homing the joints that have no absolute encoder, from the host: each joint that [HOMING] of the
// board config homes gets calibrate_encoder (hard_stop) and is polled (get_control_mode) until its
// board reports position (homed: it found its stop and backed off), not_configured (no stop within
// the joint's timeout) or a fault. `robogene can-home` runs it; the driver does not home on its
// own, since a joint driven into its stop must be free to get there (iCub's calibrator is a
// separate step too).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "robogene/can/bus.hpp"
#include "robogene/can/head_config.hpp"

namespace robogene::can {

struct HomingResult {
  std::string joint;
  bool homed = false;
  std::string detail;      // why not, or where the joint is now
  double degrees = 0.0;    // the joint's position after homing
};

// Homes `joints` (names; empty: every joint [HOMING] homes) one after another. Throws
// robogene::Error for a joint that is unknown or does not home, or a board that does not answer
// or speaks another protocol; a joint whose homing fails is reported in its result.
std::vector<HomingResult> home_joints(std::unique_ptr<Bus> bus, const HeadConfig& head,
                                      const std::vector<std::string>& joints,
                                      const std::function<void(const std::string&)>& progress = {});

}  // namespace robogene::can
