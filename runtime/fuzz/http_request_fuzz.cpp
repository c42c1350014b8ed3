// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// libFuzzer target: what a browser's request becomes (the http carrier's form decoding and
// YARP's request plan). The request bytes themselves reach the carrier in carrier_accept_fuzz;
// here the pieces are checked against properties: form encoding round-trips (decode(encode(s))
// == s for any bytes), decoding never grows the text, and every plan is one of the three kinds
// with the lines it needs.
#include <cstddef>
#include <cstdint>
#include <string>

#include "carrier/http_request.hpp"

using namespace robogene::carrier::detail;

namespace {

std::string form_encode(const std::string& s) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : s) {
    if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.') {
      out += static_cast<char>(c);
    } else if (c == ' ') {
      out += '+';
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string s(reinterpret_cast<const char*>(data), size);
  if (url_decode(form_encode(s)) != s) __builtin_trap();
  if (url_decode(s).size() > s.size()) __builtin_trap();
  const auto fields = parse_fields(s);
  for (const auto& f : fields) {
    if (f.first.size() + f.second.size() > s.size()) __builtin_trap();
  }
  // The input as a request target (GET /<s>) and as a form body.
  HttpRequest r;
  r.method = size % 2 ? "GET" : "POST";
  r.target = s;
  r.fields = fields;
  const HttpPlan plan = plan_http_request(r);
  if (plan.kind == HttpPlan::Kind::Call && plan.lines.size() != 1) __builtin_trap();
  if (plan.kind == HttpPlan::Kind::Page && plan.lines.empty()) __builtin_trap();
  return 0;
}
