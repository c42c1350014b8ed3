// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The few YARP 3 framing pieces the name server and its probe need (reference sections 3.1-3.3):
// "yarp numbers" ('Y' 'A' int32 'R' 'P'), carrier headers, the message index and PortCommand.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace robogene::name::wire {

using Header = std::array<std::uint8_t, 8>;

inline Header yarp_number(std::int32_t x) {
  auto u = static_cast<std::uint32_t>(x);
  return {'Y', 'A', static_cast<std::uint8_t>(u), static_cast<std::uint8_t>(u >> 8),
          static_cast<std::uint8_t>(u >> 16), static_cast<std::uint8_t>(u >> 24), 'R', 'P'};
}

inline std::optional<std::int32_t> read_yarp_number(const Header& h) {
  if (h[0] != 'Y' || h[1] != 'A' || h[6] != 'R' || h[7] != 'P') return std::nullopt;
  std::uint32_t u = h[2] | (h[3] << 8) | (h[4] << 16) | (static_cast<std::uint32_t>(h[5]) << 24);
  return static_cast<std::int32_t>(u);
}

inline std::int32_t le32(const std::uint8_t* p) {
  return static_cast<std::int32_t>(p[0] | (p[1] << 8) | (p[2] << 16) | (static_cast<std::uint32_t>(p[3]) << 24));
}

inline void put_le32(std::vector<std::uint8_t>& out, std::int32_t v) {
  auto u = static_cast<std::uint32_t>(v);
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(u >> (8 * i)));
}

// tcp with acks = 7777 + 3 + 128, fast_tcp = 7777 + 3.
constexpr std::int32_t kTcpSpecifier = 7777 + 3 + 128;
constexpr std::int32_t kFastTcpSpecifier = 7777 + 3;

inline bool starts_with(const Header& h, const char* text) { return std::memcmp(h.data(), text, 8) == 0; }

// One indexed message carrying the blocks given (reference 3.3): "YA 0a 00 00 00 RP", nIn, nOut=1,
// 8 x ff, the block lengths, a zero reply length, then the blocks.
inline std::vector<std::uint8_t> indexed_message(const std::vector<std::vector<std::uint8_t>>& blocks) {
  std::vector<std::uint8_t> out;
  Header h = yarp_number(10);
  out.insert(out.end(), h.begin(), h.end());
  out.push_back(static_cast<std::uint8_t>(blocks.size()));
  out.push_back(1);
  out.insert(out.end(), 8, 0xff);
  for (const auto& b : blocks) put_le32(out, static_cast<std::int32_t>(b.size()));
  put_le32(out, 0);
  for (const auto& b : blocks) out.insert(out.end(), b.begin(), b.end());
  return out;
}

// The 8-byte PortCommand for `ch` ('d', 'D', 'a', 'r') and the string form (ch 0) used for "q".
inline std::vector<std::uint8_t> port_command(char ch) { return {0, 0, 0, 0, '~', static_cast<std::uint8_t>(ch), 0, 1}; }
inline std::vector<std::uint8_t> port_command_string(const std::string& text) {
  std::vector<std::uint8_t> out;
  put_le32(out, static_cast<std::int32_t>(text.size() + 1));
  out.insert(out.end(), {'~', 0, 0, 1});
  out.insert(out.end(), text.begin(), text.end());
  out.push_back(0);
  return out;
}

}  // namespace robogene::name::wire
