// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/envelope.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace robogene {

std::string Stamp::to_text() const {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%d %.15g", static_cast<int>(sequence), time);
  return buf;
}

std::optional<Stamp> Stamp::parse(std::string_view text) {
  std::string s(text);
  const char* p = s.c_str();
  char* end = nullptr;
  long seq = std::strtol(p, &end, 10);
  if (end == p || *end != ' ') return std::nullopt;
  const char* t = end + 1;
  double time = std::strtod(t, &end);
  if (end == t || *end != '\0') return std::nullopt;
  return Stamp{static_cast<std::int32_t>(seq), time};
}

}  // namespace robogene
