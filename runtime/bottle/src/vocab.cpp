// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Vocab decoding: the packed characters back to text, zero bytes dropped as YARP's Vocab32::decode does.
#include "robogene/vocab.hpp"

namespace robogene {

std::string vocab_to_string(vocab_t v) {
  const auto bits = static_cast<std::uint32_t>(v);
  std::string out;
  for (int i = 0; i < 4; ++i) {
    const auto ch = static_cast<char>((bits >> (8 * i)) & 0xffu);
    if (ch != '\0') out += ch;
  }
  return out;
}

}  // namespace robogene
