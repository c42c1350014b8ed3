// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "sender_name.hpp"

#include "robogene/carrier/yarp_number.hpp"
#include "robogene/error.hpp"

namespace robogene::carrier::detail {

void append_binary_sender_name(std::vector<std::uint8_t>& out, const std::string& name) {
  std::size_t at = out.size();
  out.resize(at + 4);
  put_int32(out.data() + at, static_cast<std::int32_t>(name.size() + 1));
  out.insert(out.end(), name.begin(), name.end());
  out.push_back(0);
}

std::string read_binary_sender_name(Link& link, std::size_t max_length) {
  std::uint8_t len_bytes[4];
  link.reader.read_exact(len_bytes, 4);
  std::int32_t len = get_int32(len_bytes);
  if (len < 1 || static_cast<std::size_t>(len) > max_length) {
    throw ParseError(8, "handshake from " + link.stream.peer_text() + ": sender name length " +
                            std::to_string(len) + " at byte offset 8 is outside 1.." +
                            std::to_string(max_length));
  }
  std::string name(static_cast<std::size_t>(len), '\0');
  link.reader.read_exact(name.data(), name.size());
  auto nul = name.find('\0');
  if (nul != std::string::npos) name.resize(nul);
  auto space = name.find(' ');
  if (space != std::string::npos) name.resize(space);
  return name;
}

}  // namespace robogene::carrier::detail
