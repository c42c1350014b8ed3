// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// What every method of robogene_can shares (both robogene_can*.cpp include it): a thrown error
// becomes a logged false return, and per-joint vectors are checked whole before anything is sent.
#pragma once

#include <cmath>
#include <string>

#include "robogene/log.hpp"
#include "robogene_can.hpp"

namespace robogene::can {
namespace driver_detail {

inline constexpr const char* kWho = "robogene_can";

inline std::string finite_value(double v) { return std::isfinite(v) ? "" : std::to_string(v) + " is not finite"; }
inline std::string positive_value(double v) {
  return std::isfinite(v) && v > 0 ? "" : std::to_string(v) + " is not a positive number";
}

}  // namespace driver_detail

template <class F>
bool RobogeneCan::guarded(const char* what, int j, F&& f) {
  try {
    if (!link_) throw Error("the device is not open");
    f();
    return true;
  } catch (const Error& e) {
    const std::string text = std::string(what) + (j >= 0 ? " (joint " + std::to_string(j) + ")" : "") + ": " + e.what();
    log::error(driver_detail::kWho, text);
    std::lock_guard<std::mutex> lock(mutex_);
    last_error_ = text;
    return false;
  }
}

template <class T, class Check, class F>
bool RobogeneCan::for_each(const char* what, const std::vector<T>& values, Check&& check, F&& f) {
  // Every value is checked before anything is sent, so one bad entry changes nothing.
  const bool valid = guarded(what, -1, [&] {
    if (values.size() != head_.joints.size()) {
      throw Error(std::to_string(values.size()) + " values for " + std::to_string(head_.joints.size()) + " joints");
    }
    for (std::size_t j = 0; j < values.size(); ++j) {
      const std::string problem = check(values[j]);
      if (!problem.empty()) throw Error("value " + std::to_string(j) + ": " + problem);
    }
  });
  if (!valid) return false;
  bool ok = true;
  for (std::size_t j = 0; j < values.size(); ++j) ok = f(static_cast<int>(j), values[j]) && ok;
  return ok;
}

template <class T, class F>
bool RobogeneCan::read_each(std::vector<T>& out, F&& f) {
  out.assign(head_.joints.size(), T{});
  bool ok = true;
  for (std::size_t j = 0; j < out.size(); ++j) {
    T v{};
    ok = f(static_cast<int>(j), v) && ok;
    out[j] = v;
  }
  return ok;
}

}  // namespace robogene::can
