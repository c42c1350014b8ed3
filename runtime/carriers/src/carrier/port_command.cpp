// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/carrier/port_command.hpp"

#include <cstring>

#include "robogene/carrier/yarp_number.hpp"
#include "robogene/error.hpp"

namespace robogene::carrier {

void PortCommand::encode(std::vector<std::uint8_t>& out) const {
  std::size_t at = out.size();
  out.resize(at + 8);
  std::uint8_t* h = out.data() + at;
  put_int32(h, text.empty() ? 0 : static_cast<std::int32_t>(text.size() + 1));
  h[4] = '~';
  h[5] = text.empty() ? static_cast<std::uint8_t>(key) : 0;
  h[6] = 0;
  h[7] = 1;
  if (!text.empty()) {
    out.insert(out.end(), text.begin(), text.end());
    out.push_back(0);
  }
}

std::size_t PortCommand::decode_header(const std::uint8_t* h, std::size_t available_after,
                                       std::size_t offset, PortCommand& out) {
  if (h[4] != '~') {
    throw ParseError(offset + 4, "PortCommand marker: expected '~' (0x7e) at byte offset " +
                                     std::to_string(offset + 4) + ", found 0x" +
                                     [&] {
                                       char b[3];
                                       std::snprintf(b, sizeof b, "%02x", h[4]);
                                       return std::string(b);
                                     }());
  }
  out.key = static_cast<char>(h[5]);
  out.text.clear();
  if (h[5] != 0) return 0;
  std::int32_t len = get_int32(h);
  if (len < 0 || static_cast<std::size_t>(len) > available_after) {
    throw ParseError(offset, "PortCommand string length " + std::to_string(len) +
                                 " does not fit the " + std::to_string(available_after) +
                                 " bytes left in the message");
  }
  return static_cast<std::size_t>(len);
}

void PortCommand::set_string(const std::uint8_t* data, std::size_t size) {
  const void* nul = std::memchr(data, 0, size);
  std::size_t n = nul ? static_cast<std::size_t>(static_cast<const std::uint8_t*>(nul) - data) : size;
  text.assign(reinterpret_cast<const char*>(data), n);
  key = text.empty() ? 0 : text[0];
}

std::string PortCommand::envelope() const {
  if ((key == 'd' || key == 'D') && text.size() > 2) return text.substr(2);
  return {};
}

}  // namespace robogene::carrier
