// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Number classification, parsing and formatting for the text form (reference section 2).
#include "number_text.hpp"

#include <charconv>
#include <clocale>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <locale.h>  // newlocale, strtod_l (POSIX / glibc)

#include "robogene/error.hpp"

namespace robogene::text {

namespace {

bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }
bool is_hex_letter(char c) noexcept { return (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

// The "C" locale, created once, so that strtod never reads ',' as the decimal point.
locale_t c_locale() {
  static const locale_t loc = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
  return loc;
}

}  // namespace

NumberKind classify_number(std::string_view s) noexcept {
  if (s.empty()) return NumberKind::NotANumber;
  if (s == "inf" || s == "-inf" || s == "nan") return NumberKind::Float;
  const char first = s[0];
  if (!(is_digit(first) || first == '+' || first == '-' || first == '.')) return NumberKind::NotANumber;
  if (first == '.' && s.size() == 1) return NumberKind::NotANumber;

  // A "preamble" of zeros, signs and one x/X may precede the digits (`-0x1F`, `+5`, `010`).
  bool preamble = true;
  bool hex = false;
  std::size_t hex_at = 0;
  int periods = 0;
  int signs = 0;
  bool float_like = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '.') {
      float_like = true;
      if (++periods > 1) return NumberKind::NotANumber;
    }
    if (!hex && (c == 'e' || c == 'E')) float_like = true;
    if (preamble && (c == 'x' || c == 'X')) {
      hex = true;
      hex_at = i;
      continue;
    }
    if (preamble && (c == '0' || c == '+' || c == '-')) {
      if ((c == '+' || c == '-') && ++signs > 1) return NumberKind::NotANumber;
      continue;
    }
    preamble = false;
    const bool allowed = is_digit(c) || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-' ||
                         (hex && is_hex_letter(c));
    if (!allowed) return NumberKind::NotANumber;
  }
  if (hex && s.size() - (hex_at + 1) > 8) return NumberKind::NotANumber;  // YARP: 32-bit hex only
  return float_like ? NumberKind::Float : NumberKind::Integer;
}

Value parse_integer(std::string_view token) {
  const std::string s(token);  // strtoll needs a terminator
  const long long v = std::strtoll(s.c_str(), nullptr, 0);  // base 0: 0x.. hex, 0.. octal
  if (v >= std::numeric_limits<std::int32_t>::min() && v <= std::numeric_limits<std::int32_t>::max()) {
    return Value::int32(static_cast<std::int32_t>(v));
  }
  return Value::int64(static_cast<std::int64_t>(v));
}

double parse_float(std::string_view token) {
  if (token == "inf") return std::numeric_limits<double>::infinity();
  if (token == "-inf") return -std::numeric_limits<double>::infinity();
  if (token == "nan") return std::numeric_limits<double>::quiet_NaN();
  const std::string s(token);
  const locale_t loc = c_locale();
  if (loc == static_cast<locale_t>(nullptr)) throw Error("cannot create the \"C\" locale to read the number " + s);
  return strtod_l(s.c_str(), nullptr, loc);
}

std::string format_float(double x) {
  if (std::isnan(x)) return "nan";  // glibc's "-nan" would read back as a string
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[64];
  // to_chars with a precision is specified as printf("%.*g") in the "C" locale.
  const auto res = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 21);
  std::string out(buf, res.ptr);
  if (out.find('.') == std::string::npos && out.find('e') == std::string::npos) out += ".0";
  return out;
}

}  // namespace robogene::text
