// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// libFuzzer target: arbitrary text into the text parser. Anything must end as a Bottle or a
// ParseError; the canonical text of a parsed Bottle must parse again to the same canonical text,
// and the Bottle must survive a binary round trip.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "robogene/bottle.hpp"
#include "robogene/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  (void)robogene::Bottle::text_is_complete(text);
  robogene::Bottle parsed;
  try {
    parsed = robogene::Bottle::from_text(text);
  } catch (const robogene::ParseError& e) {
    if (e.position() == 0 || e.position() > size + 1) __builtin_trap();  // columns are 1-based, in range
    return 0;
  }
  const std::string canonical = parsed.to_text();
  if (robogene::Bottle::from_text(canonical).to_text() != canonical) __builtin_trap();
  const robogene::Bottle decoded = robogene::Bottle::from_bytes(parsed.to_bytes());
  if (decoded.size() != parsed.size()) __builtin_trap();
  return 0;
}
