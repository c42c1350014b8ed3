// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Numbers in the text form: YARP 3's classification of a bare token (BottleImpl::smartAdd) and
// its float rendering (%.21g plus ".0"), both independent of the C locale.
#pragma once

#include <string>
#include <string_view>

#include "robogene/value.hpp"

namespace robogene::text {

enum class NumberKind { NotANumber, Integer, Float };

// How YARP reads a bare token: integer (incl. hex `0x1F`, octal `010`, a lone sign), float (has
// `.` or `e`, or is exactly `inf`, `-inf`, `nan`), or not a number (then it is a string).
NumberKind classify_number(std::string_view token) noexcept;

// The value of a token classified as Integer: int32 when it fits, int64 otherwise.
Value parse_integer(std::string_view token);

// The value of a token classified as Float.
double parse_float(std::string_view token);

// `%.21g`, '.' as decimal point whatever the locale, ".0" appended to integral results.
std::string format_float(double x);

}  // namespace robogene::text
