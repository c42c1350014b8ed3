// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The 8-byte "yarp number" `Y A <int32 LE> R P`: carrier headers, the reply to a header (a port
// number), the index length (10) and the ack (0) all use it (reference section 3.1).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

namespace robogene::carrier {

using Header = std::array<std::uint8_t, 8>;

Header make_yarp_number(std::int32_t x);
// The number inside `bytes`, or nullopt when they are not `YA....RP`.
std::optional<std::int32_t> read_yarp_number(const std::uint8_t* bytes);

// Carrier headers: 7777 + specifier (+128 for tcp with acks).
constexpr std::int32_t kTcpSpecifier = 7777 + 3 + 128;
constexpr std::int32_t kFastTcpSpecifier = 7777 + 3;
constexpr std::int32_t kUdpSpecifier = 7777 + 0;
constexpr std::int32_t kMcastSpecifier = 7777 + 1;
constexpr std::int32_t kIndexLength = 10;

// Little-endian int32 helpers used by every binary carrier.
void put_int32(std::uint8_t* out, std::int32_t v);
std::int32_t get_int32(const std::uint8_t* in);

}  // namespace robogene::carrier
