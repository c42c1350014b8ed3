// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The C++ codec driven line by line, so the Python tests can hold it to the Python codec:
//   encode <text form>   ->  ok <candump frame, e.g. 001#1BE80300001900>   or  error <what>
//   decode <candump frame> ->  ok <text form>                              or  error <what>
#include <cstdio>
#include <iostream>
#include <string>

#include "motor_control.hpp"

namespace {

using robogene::can::Frame;

// "ID#HEX" as candump writes it; the hex may be empty.
bool parse_frame(const std::string& s, Frame& f, std::string& why) {
  const auto hash = s.find('#');
  if (hash == std::string::npos || hash == 0 || hash > 3) {
    why = "expected ID#DATA, got '" + s + "'";
    return false;
  }
  f.id = static_cast<std::uint16_t>(std::stoul(s.substr(0, hash), nullptr, 16));
  const std::string hex = s.substr(hash + 1);
  if (hex.size() % 2 != 0 || hex.size() > 16) {
    why = "bad data '" + hex + "'";
    return false;
  }
  f.len = static_cast<std::uint8_t>(hex.size() / 2);
  for (std::size_t i = 0; i < f.len; ++i) {
    f.data[i] = static_cast<std::uint8_t>(std::stoul(hex.substr(2 * i, 2), nullptr, 16));
  }
  return true;
}

std::string frame_text(const Frame& f) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%03X", static_cast<unsigned>(f.id));
  std::string s = std::string(buf) + "#";
  for (unsigned i = 0; i < f.len; ++i) {
    std::snprintf(buf, sizeof buf, "%02X", f.data[i]);
    s += buf;
  }
  return s;
}

}  // namespace

int main() {
  std::string line;
  while (std::getline(std::cin, line)) {
    const auto space = line.find(' ');
    const std::string verb = line.substr(0, space);
    const std::string rest = space == std::string::npos ? "" : line.substr(space + 1);
    try {
      if (verb == "encode") {
        const std::string frame = frame_text(robogene::can::encode(robogene::can::from_text(rest)));
        std::cout << "ok " << frame << "\n";
      } else if (verb == "decode") {
        Frame f;
        std::string why;
        if (!parse_frame(rest, f, why)) {
          std::cout << "error " << why << "\n";
        } else {
          const std::string text = robogene::can::to_text(robogene::can::decode(f));
          std::cout << "ok " << text << "\n";
        }
      } else {
        std::cout << "error unknown verb '" << verb << "'\n";
      }
    } catch (const robogene::can::CodecError& e) {
      std::cout << "error " << e.what() << "\n";
    }
    std::cout.flush();
  }
  return 0;
}
