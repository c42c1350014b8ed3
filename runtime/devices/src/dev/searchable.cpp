// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Typed reads of a configuration: one place that turns a wrong value into a message naming it.
#include <cmath>
#include <cstdio>
#include <string>

#include "robogene/dev/property.hpp"

namespace robogene::dev {
namespace {

// Bounds are the program's own round numbers: print them as people write them (1e-09, 64).
std::string shortest(double d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", d);
  return buf;
}

[[noreturn]] void fail(const Searchable& s, std::string_view key, const std::string& what) {
  throw ConfigError(s.origin(key) + ": key '" + std::string(key) + "': " + what);
}

}  // namespace

const Value& Searchable::require(std::string_view key) const {
  const Value& v = find(key);
  if (v.is_null()) {
    throw ConfigError(source() + ": missing key '" + std::string(key) + "'");
  }
  return v;
}

std::string Searchable::get_string(std::string_view key, std::string_view fallback) const {
  const Value& v = find(key);
  if (v.is_null()) return std::string(fallback);
  if (v.is_string()) return v.as_string();
  // true and false (a bare flag: `--from` without its file) parse as the vocabs [1] and 0: no word.
  if (v.is_vocab() && v.as_vocab() != vocab("1") && v.as_vocab() != 0) return vocab_to_string(v.as_vocab());
  fail(*this, key, "expected a word or a \"string\", got " + v.to_text());
}

std::int32_t Searchable::get_int(std::string_view key, std::int32_t fallback, std::int32_t min,
                                 std::int32_t max) const {
  const Value& v = find(key);
  if (v.is_null()) return fallback;
  if (!v.is_int()) fail(*this, key, "expected an integer, got " + v.to_text());
  const std::int64_t n = v.as_int64();
  if (n < min || n > max) {
    fail(*this, key, std::to_string(n) + " is outside [" + std::to_string(min) + ", " +
                         std::to_string(max) + "]");
  }
  return static_cast<std::int32_t>(n);
}

double Searchable::get_float(std::string_view key, double fallback, double min, double max) const {
  const Value& v = find(key);
  if (v.is_null()) return fallback;
  if (!v.is_number()) fail(*this, key, "expected a number, got " + v.to_text());
  const double d = v.as_float64();
  if (!std::isfinite(d) || d < min || d > max) {
    fail(*this, key, v.to_text() + " is outside [" + shortest(min) + ", " + shortest(max) + "]");
  }
  return d;
}

bool Searchable::get_bool(std::string_view key, bool fallback) const {
  const Value& v = find(key);
  if (v.is_null()) return fallback;
  if (v.is_vocab() && (v.as_vocab() == vocab("1") || v.as_vocab() == 0)) {
    return v.as_vocab() != 0;  // true / false parse as the vocabs [1] and 0
  }
  if (v.is_int() && (v.as_int64() == 0 || v.as_int64() == 1)) return v.as_int64() == 1;
  if (v.is_string() && (v.as_string() == "true" || v.as_string() == "false")) {
    return v.as_string() == "true";
  }
  fail(*this, key, "expected true or false, got " + v.to_text());
}

}  // namespace robogene::dev
