// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "sim_clock.hpp"

#include <cmath>

namespace robogene::dev {

void SimClock::configure(const Searchable& config) {
  const std::string kind = config.get_string("clock", "wall");
  if (kind != "wall" && kind != "manual") {
    throw ConfigError(config.origin("clock") + ": key 'clock': expected wall or manual, got '" +
                      kind + "'");
  }
  manual_ = kind == "manual";
  manual_now_ = 0.0;
  start_ = std::chrono::steady_clock::now();
}

double SimClock::now() const {
  if (manual_) return manual_now_;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool SimClock::advance(double seconds) {
  if (!manual_ || !std::isfinite(seconds) || seconds < 0.0) return false;
  manual_now_ += seconds;
  return true;
}

}  // namespace robogene::dev
