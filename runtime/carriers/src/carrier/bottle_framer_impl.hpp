// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Reads one binary Bottle of unannounced length from any source with read_exact(void*, size_t)
// (a tcp StreamReader, a shared-memory ring); see bottle_framer.hpp (private to src/carrier).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "grow_read.hpp"
#include "robogene/bottle.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/error.hpp"

namespace robogene::carrier::detail {

inline constexpr std::int32_t kFramerList = 0x100;
inline constexpr std::int32_t kFramerDict = 0x200;

template <typename In>
class BottleFramer {
 public:
  BottleFramer(In& in, std::vector<std::uint8_t>& out, const DecodeLimits& limits,
               const std::uint8_t* first8, ReceivingBytes* budget)
      : in_(in), out_(out), limits_(limits), budget_(budget), start_(out.size()) {
    if (first8) out_.insert(out_.end(), first8, first8 + 8);
  }

  void bottle(std::size_t depth) {
    std::int32_t tag = int32();
    if ((tag & kFramerList) == 0) fail(4, "top-level tag 0x" + hex(tag) + " is not a list");
    if (tag & kFramerDict) {
      // A dict body is itself a complete bottle.
      bottle(depth + 1);
      return;
    }
    body(tag & 0xff, depth);
  }

 private:
  void body(std::int32_t sub, std::size_t depth) {
    if (depth > limits_.max_depth) fail(0, "lists nested deeper than " + std::to_string(limits_.max_depth));
    std::int32_t count = int32();
    if (count < 0) fail(4, "negative item count " + std::to_string(count));
    for (std::int32_t i = 0; i < count; ++i) item(sub ? sub : int32(), depth);
  }

  void item(std::int32_t tag, std::size_t depth) {
    if (tag & (kFramerList | kFramerDict)) {
      if ((tag & kFramerDict) && !(tag & kFramerList)) fail(4, "dict tag without list bit");
      if (tag & kFramerDict) {
        bottle(depth + 1);
      } else {
        body(tag & 0xff, depth + 1);
      }
      return;
    }
    switch (tag) {
      case 32: take(1); break;                  // int8
      case 64: take(2); break;                  // int16
      case 1: case 9: case 128: take(4); break; // int32, vocab, float32
      case 17: case 10: take(8); break;         // int64, float64
      case 4: case 12: {                        // string, blob
        std::int32_t len = int32();
        if (len < 0) fail(4, "negative string/blob length " + std::to_string(len));
        take(static_cast<std::size_t>(len));
        break;
      }
      default:
        fail(4, "unknown type tag 0x" + hex(tag));
    }
  }

  std::int32_t int32() {
    std::size_t at = start_ + cursor_;
    take(4);
    return get_int32(out_.data() + at);
  }

  // Makes the next n bytes of the bottle available in out_ (some may have been preloaded).
  void take(std::size_t n) {
    if (cursor_ + n > limits_.max_bytes) {
      fail(0, "reply larger than the " + std::to_string(limits_.max_bytes) + "-byte limit");
    }
    std::size_t need_end = start_ + cursor_ + n;
    if (out_.size() < need_end) append_growing(in_, out_, need_end - out_.size(), budget_);
    cursor_ += n;
  }

  [[noreturn]] void fail(std::size_t back, const std::string& what) {
    std::size_t off = cursor_ >= back ? cursor_ - back : 0;
    throw ParseError(off, "reply bottle: " + what + " at byte offset " + std::to_string(off));
  }

  static std::string hex(std::int32_t v) {
    char b[16];
    std::snprintf(b, sizeof b, "%x", static_cast<unsigned>(v));
    return b;
  }

  In& in_;
  std::vector<std::uint8_t>& out_;
  const DecodeLimits& limits_;
  ReceivingBytes* budget_;  // counts the bytes as they arrive (may be null)
  std::size_t start_;
  std::size_t cursor_ = 0;
};

template <typename In>
void read_bottle_bytes_from(In& in, std::vector<std::uint8_t>& out, const DecodeLimits& limits,
                            const std::uint8_t* first8 = nullptr, ReceivingBytes* budget = nullptr) {
  BottleFramer<In> f(in, out, limits, first8, budget);
  f.bottle(0);
}

}  // namespace robogene::carrier::detail
