// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name/name_reply.hpp"

#include <algorithm>

namespace robogene::name {

std::string old_style_line(const Bottle& items) {
  std::string text = items.to_text();
  text.erase(std::remove(text.begin(), text.end(), '"'), text.end());
  return text;
}

std::string NameReply::to_text_wire() const {
  if (!old_style) return bottle.to_text() + "\r\n";
  std::string out;
  for (const auto& line : lines) {
    if (line.empty()) continue;  // yarpserver skips empty lines
    out += line;
    out += "\r\n";
  }
  out += "*** end of message\r\n";
  return out;
}

std::vector<std::uint8_t> NameReply::to_binary_wire() const {
  if (!old_style) return bottle.to_bytes();
  std::string text = to_text_wire();
  return std::vector<std::uint8_t>(text.begin(), text.end());
}

}  // namespace robogene::name
