// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Helpers for wire-level tests: hex strings (as printed in the captures) to bytes, a raw TCP
// peer on an ephemeral port, reading what a peer sent with a deadline.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "robogene/net/tcp_listener.hpp"
#include "robogene/net/tcp_stream.hpp"
#include "robogene/error.hpp"

namespace robogene::test {

// "59 41 e4 1e" -> bytes; whitespace and newlines ignored.
inline std::vector<std::uint8_t> hex(const std::string& text) {
  std::vector<std::uint8_t> out;
  std::string digits;
  for (char c : text) {
    if (std::isxdigit(static_cast<unsigned char>(c))) digits.push_back(c);
  }
  for (std::size_t i = 0; i + 1 < digits.size(); i += 2) {
    out.push_back(static_cast<std::uint8_t>(std::stoi(digits.substr(i, 2), nullptr, 16)));
  }
  return out;
}

inline std::vector<std::uint8_t> bytes(const std::string& s) {
  return std::vector<std::uint8_t>(s.begin(), s.end());
}

inline std::vector<std::uint8_t> read_n(net::TcpStream& s, std::size_t n) {
  std::vector<std::uint8_t> out(n);
  s.set_read_timeout(std::chrono::milliseconds(5000));
  s.read_exact(out.data(), n);
  return out;
}

// Reads until `terminator` has arrived (or 5 s pass, then whatever came).
inline std::string read_until(net::TcpStream& s, const std::string& terminator) {
  std::string got;
  s.set_read_timeout(std::chrono::milliseconds(5000));
  char buf[4096];
  while (got.find(terminator) == std::string::npos) {
    std::size_t n = 0;
    try {
      n = s.read_some(buf, sizeof buf);
    } catch (...) {
      break;
    }
    if (n == 0) break;
    got.append(buf, n);
  }
  return got;
}

inline void send(net::TcpStream& s, const std::vector<std::uint8_t>& b) { s.write_all(b.data(), b.size()); }
inline void send(net::TcpStream& s, const std::string& b) { s.write_all(b.data(), b.size()); }

}  // namespace robogene::test
