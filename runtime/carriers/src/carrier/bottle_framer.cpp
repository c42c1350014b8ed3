// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/carrier/bottle_framer.hpp"

#include "bottle_framer_impl.hpp"

namespace robogene::carrier {

void read_bottle_bytes(net::StreamReader& in, std::vector<std::uint8_t>& out,
                       const DecodeLimits& limits, const std::uint8_t* first8, ReceivingBytes* budget) {
  detail::read_bottle_bytes_from(in, out, limits, first8, budget);
}

}  // namespace robogene::carrier
