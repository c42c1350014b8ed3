// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The PortCommand that opens every message on an escaping carrier (reference section 3.3):
// binary `int32 len, '~', ch, 0, 1` followed, when ch is 0, by a NUL-terminated command string
// ("q", "d <envelope>", "D <envelope>"). Text carriers send the same command as a line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace robogene::carrier {

struct PortCommand {
  char key = 'D';     // 'd' data+reply, 'D' data only, 'a' admin, 'r' reverse, 'q' quit, ...
  std::string text;   // the ch-0 string ("D 12 1795.5"), empty for single-character commands

  // Binary form: 8 bytes, plus text + NUL when `text` is set (then the header's ch is 0).
  void encode(std::vector<std::uint8_t>& out) const;
  // Decodes the 8-byte header; returns the length of the string that follows (0 if none).
  // Throws ParseError naming `offset + i` for a bad marker or length.
  static std::size_t decode_header(const std::uint8_t* header8, std::size_t available_after,
                                   std::size_t offset, PortCommand& out);
  // Completes a ch-0 command from its string (up to the first NUL).
  void set_string(const std::uint8_t* data, std::size_t size);
  // The envelope carried by "d <env>" / "D <env>" ("" when none).
  std::string envelope() const;
};

}  // namespace robogene::carrier
