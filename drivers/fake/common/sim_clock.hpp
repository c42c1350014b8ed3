// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The time of a simulated device: a monotonic wall clock, or a manual one moved by advance().
#pragma once

#include <chrono>
#include <string>

#include "robogene/dev/property.hpp"

namespace robogene::dev {

class SimClock {
 public:
  // Reads `clock wall|manual` from the configuration (default wall).
  void configure(const Searchable& config);
  bool manual() const { return manual_; }
  double now() const;
  bool advance(double seconds);  // manual clocks only; seconds >= 0 and finite

 private:
  bool manual_ = false;
  double manual_now_ = 0.0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace robogene::dev
