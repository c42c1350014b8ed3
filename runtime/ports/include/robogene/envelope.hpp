// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Message envelopes as YARP's Stamp writes them in text: "<seq> <time>" with time printed by
// "%.15g" (DBL_DIG), e.g. "1053 1795328338.10597". Sent as the PortCommand "D <envelope>".
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace robogene {

struct Stamp {
  std::int32_t sequence = 0;
  double time = 0;

  std::string to_text() const;
  // nullopt when `text` is not "<int> <number>".
  static std::optional<Stamp> parse(std::string_view text);
};

}  // namespace robogene
