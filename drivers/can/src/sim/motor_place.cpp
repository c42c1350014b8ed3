// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/sim/motor_place.hpp"

#include "robogene/error.hpp"

namespace robogene::can::sim {

MotorPlace motor_place(const HeadConfig& head, const std::string& name) {
  std::string known;
  for (const auto& b : head.boards) {
    for (int m = 0; m < 2; ++m) {
      std::string motor;
      if (b.coupling) {
        motor = b.coupling->motors[static_cast<std::size_t>(m)];
      } else if (b.joints[static_cast<std::size_t>(m)] >= 0) {
        motor = head.joints[static_cast<std::size_t>(b.joints[static_cast<std::size_t>(m)])].name;
      }
      if (motor.empty()) continue;
      if (motor == name) return MotorPlace{b.address, m};
      known += (known.empty() ? "" : ", ") + motor;
    }
  }
  throw Error("'" + name + "' is no motor of " + head.source + " (the motors: " + known +
              "; on a coupled board name its motors, not its joints)");
}

}  // namespace robogene::can::sim
