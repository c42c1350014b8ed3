// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/frame.hpp"

#include <algorithm>
#include <cstdio>

#include "robogene/error.hpp"

namespace robogene::can {

Frame::Frame(std::uint16_t frame_id, const std::vector<std::uint8_t>& bytes) : id(frame_id) {
  if (bytes.size() > kMaxDataLength) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "CAN frame 0x%03X: %zu data bytes, at most 8 fit in a classic frame",
                  frame_id, bytes.size());
    throw Error(buf);
  }
  len = static_cast<std::uint8_t>(bytes.size());
  std::copy(bytes.begin(), bytes.end(), data.begin());
  validate(*this);
}

bool Frame::operator==(const Frame& o) const {
  return id == o.id && len == o.len && std::equal(data.begin(), data.begin() + len, o.data.begin());
}

void validate(const Frame& f) {
  if (f.id > kMaxStandardId) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "CAN frame id 0x%X does not fit 11 bits (largest is 0x7FF)", f.id);
    throw Error(buf);
  }
  if (f.len > kMaxDataLength) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "CAN frame 0x%03X: length %u is more than 8 bytes", f.id,
                  static_cast<unsigned>(f.len));
    throw Error(buf);
  }
}

std::string to_string(const Frame& f) {
  char buf[3 + 1 + 16 + 1];
  int n = std::snprintf(buf, sizeof buf, "%03X#", static_cast<unsigned>(f.id & 0xFFF));
  const std::uint8_t len = std::min<std::uint8_t>(f.len, kMaxDataLength);
  for (std::uint8_t i = 0; i < len; ++i) {
    n += std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), "%02X", f.data[i]);
  }
  return std::string(buf, static_cast<std::size_t>(n));
}

bool passes(const std::vector<Filter>& filters, std::uint16_t frame_id) {
  if (filters.empty()) return true;
  return std::any_of(filters.begin(), filters.end(),
                     [&](const Filter& flt) { return flt.matches(frame_id); });
}

}  // namespace robogene::can
