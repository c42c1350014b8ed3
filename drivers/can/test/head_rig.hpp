// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Helpers for the driver tests: the head config pointed at a bus, and waiting on a condition.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <thread>

#include "head_config_fixture.hpp"
#include "robogene/dev/property.hpp"

namespace robogene::can::testing {

inline dev::Property driver_config(const std::string& bus) {
  dev::Property p = dev::Property::from_ini_file(head_ini_path());
  p.put("device", Value(std::string("robogene_can")));
  p.put("bus", Value(bus));
  return p;
}

// Polls `ok` every 10 ms until it holds or `seconds` pass.
inline bool eventually(double seconds, const std::function<bool()>& ok) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < deadline) {
    if (ok()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return ok();
}

}  // namespace robogene::can::testing
