// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/carrier/message.hpp"

#include <string_view>

namespace robogene::carrier {

namespace {

// Puts the detached bodies back into the blobs they were cut from, in depth-first order.
template <typename Take>
void refill(Bottle& b, std::size_t& ordinal, std::size_t& next, const std::vector<std::size_t>& slots,
            Take&& take) {
  for (Value& v : b) {
    if (next == slots.size()) return;
    if (v.is_list()) {
      refill(v.as_list(), ordinal, next, slots, take);
    } else if (v.is_blob()) {
      if (ordinal == slots[next]) v.as_blob() = take(next++);
      ++ordinal;
    }
  }
}

}  // namespace

Bottle InboundMessage::bottle(const DecodeLimits& limits) const {
  if (text_mode) {
    return Bottle::from_text(
        std::string_view(reinterpret_cast<const char*>(payload.data()), payload.size()));
  }
  Bottle b = Bottle::from_bytes(payload.data(), payload.size(), limits);
  std::size_t ordinal = 0, next = 0;
  refill(b, ordinal, next, detached_blob_ordinals, [&](std::size_t i) { return detached_blobs[i]; });
  return b;
}

Bottle InboundMessage::take_bottle(const DecodeLimits& limits) {
  if (text_mode || detached_blobs.empty()) return bottle(limits);
  Bottle b = Bottle::from_bytes(payload.data(), payload.size(), limits);
  std::size_t ordinal = 0, next = 0;
  refill(b, ordinal, next, detached_blob_ordinals,
         [&](std::size_t i) { return std::move(detached_blobs[i]); });
  detached_blobs.clear();
  detached_blob_ordinals.clear();
  return b;
}

void InboundMessage::recycle(Bottle& b) {
  for (Value& v : b) {
    if (v.is_list()) {
      recycle(v.as_list());
    } else if (v.is_blob() && v.as_blob().capacity() >= 64 * 1024 && spare_blobs.size() < 8) {
      spare_blobs.push_back(std::move(v.as_blob()));
    }
  }
}

}  // namespace robogene::carrier
