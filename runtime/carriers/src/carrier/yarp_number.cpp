// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/carrier/yarp_number.hpp"

namespace robogene::carrier {

void put_int32(std::uint8_t* out, std::int32_t v) {
  auto u = static_cast<std::uint32_t>(v);
  out[0] = static_cast<std::uint8_t>(u);
  out[1] = static_cast<std::uint8_t>(u >> 8);
  out[2] = static_cast<std::uint8_t>(u >> 16);
  out[3] = static_cast<std::uint8_t>(u >> 24);
}

std::int32_t get_int32(const std::uint8_t* in) {
  std::uint32_t u = static_cast<std::uint32_t>(in[0]) | (static_cast<std::uint32_t>(in[1]) << 8) |
                    (static_cast<std::uint32_t>(in[2]) << 16) |
                    (static_cast<std::uint32_t>(in[3]) << 24);
  return static_cast<std::int32_t>(u);
}

Header make_yarp_number(std::int32_t x) {
  Header h{'Y', 'A', 0, 0, 0, 0, 'R', 'P'};
  put_int32(h.data() + 2, x);
  return h;
}

std::optional<std::int32_t> read_yarp_number(const std::uint8_t* b) {
  if (b[0] != 'Y' || b[1] != 'A' || b[6] != 'R' || b[7] != 'P') return std::nullopt;
  return get_int32(b + 2);
}

}  // namespace robogene::carrier
