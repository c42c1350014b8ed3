// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// libFuzzer target: arbitrary bytes into the binary decoder. Anything must end as a Bottle or a
// ParseError; a decoded Bottle must encode again, and that encoding must decode.
#include <cstddef>
#include <cstdint>

#include "robogene/bottle.hpp"
#include "robogene/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  robogene::DecodeLimits limits;
  limits.max_bytes = 1u << 20;
  robogene::Bottle decoded;
  try {
    decoded = robogene::Bottle::from_bytes(data, size, limits);
  } catch (const robogene::ParseError&) {
    return 0;
  }
  const auto bytes = decoded.to_bytes();
  if (bytes.size() != decoded.encoded_size()) __builtin_trap();
  // Decoding our own output never fails. (It may be shorter: one trailing NUL of a string is
  // dropped per read, and a dict comes back as a list.)
  const robogene::Bottle again = robogene::Bottle::from_bytes(bytes);
  if (again.size() != decoded.size()) __builtin_trap();
  (void)decoded.to_text();
  return 0;
}
