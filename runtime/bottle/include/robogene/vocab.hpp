// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Vocabs: up to four ASCII characters packed little-endian into an int32, as YARP 3 does
// (createVocab32). In text they read `[set]`; on the wire they are the characters themselves.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace robogene {

using vocab_t = std::int32_t;

// Compile-time vocab from a literal: vocab("set"). Longer strings are truncated to 4 chars.
constexpr vocab_t vocab(std::string_view s) noexcept {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < s.size() && i < 4; ++i) {
    v |= static_cast<std::uint32_t>(static_cast<unsigned char>(s[i])) << (8 * i);
  }
  return static_cast<vocab_t>(v);
}

// The characters of a vocab, zero bytes dropped (Vocab32::decode).
std::string vocab_to_string(vocab_t v);

}  // namespace robogene
