// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/carrier/message.hpp"

#include <string_view>

namespace robogene::carrier {

Bottle InboundMessage::bottle(const DecodeLimits& limits) const {
  if (text_mode) {
    return Bottle::from_text(
        std::string_view(reinterpret_cast<const char*>(payload.data()), payload.size()));
  }
  return Bottle::from_bytes(payload.data(), payload.size(), limits);
}

}  // namespace robogene::carrier
