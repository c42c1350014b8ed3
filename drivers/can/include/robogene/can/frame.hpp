// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A classic CAN data frame with an 11-bit (standard) identifier: the only kind the head's boards
// speak (the facts: "extended frame ID has been removed"). Filters use SocketCAN's rule, so the
// same filter means the same thing on every backend.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace robogene::can {

constexpr std::uint16_t kMaxStandardId = 0x7FF;
constexpr std::uint8_t kMaxDataLength = 8;

struct Frame {
  std::uint16_t id = 0;  // 11-bit identifier
  std::uint8_t len = 0;  // 0..8
  std::array<std::uint8_t, kMaxDataLength> data{};

  Frame() = default;
  // Throws robogene::Error when id > 0x7FF or more than 8 bytes are given.
  Frame(std::uint16_t id, const std::vector<std::uint8_t>& bytes);

  bool operator==(const Frame& o) const;
  bool operator!=(const Frame& o) const { return !(*this == o); }
};

// Throws robogene::Error naming the field when id or len is out of range (frames built field by
// field are checked before they reach a bus).
void validate(const Frame& f);

// candump's compact form: "123#DEADBEEF" (upper-case hex, no spaces).
std::string to_string(const Frame& f);

// A frame passes when (frame.id & mask) == (id & mask), as CAN_RAW_FILTER decides.
struct Filter {
  std::uint16_t id = 0;
  std::uint16_t mask = 0;
  bool matches(std::uint16_t frame_id) const { return (frame_id & mask) == (id & mask); }
};

// An empty list passes every frame (a bus without filters).
bool passes(const std::vector<Filter>& filters, std::uint16_t frame_id);

}  // namespace robogene::can
