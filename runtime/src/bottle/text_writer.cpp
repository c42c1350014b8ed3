// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Text rendering as YARP 3's toString does (reference section 2, "Rendering"): what `yarp read`
// prints and what the text carriers send.
#include <string>

#include "number_text.hpp"
#include "robogene/bottle.hpp"

namespace robogene {

namespace {

bool is_letter(char c) noexcept { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_inner(char c) noexcept { return (c >= '0' && c <= '9') || c == '.' || c == '-'; }

// YARP writes a string bare when it cannot be mistaken for anything else. We also quote the
// three words that would read back as another type (`null` -> vocab, `inf`/`nan` -> float),
// where YARP would print them bare and lose the type on the way back.
bool needs_quotes(const std::string& s) noexcept {
  if (s.empty() || s == "true" || s == "false" || s == "null" || s == "inf" || s == "nan") return true;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (is_letter(c)) continue;
    if (i > 0 && is_inner(c)) continue;
    return true;
  }
  return false;
}

void append_string(std::string& out, const std::string& s) {
  if (!needs_quotes(s)) {
    out += s;
    return;
  }
  out += '"';
  for (const char c : s) {
    switch (c) {
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\0': out += "\\0"; break;
      case '\\': out += "\\\\"; break;
      case '"': out += "\\\""; break;
      default: out += c; break;
    }
  }
  out += '"';
}

void append_value(std::string& out, const Value& v);

void append_items(std::string& out, const Bottle& b) {
  bool first = true;
  for (const Value& v : b) {
    if (!first) out += ' ';
    first = false;
    append_value(out, v);
  }
}

void append_value(std::string& out, const Value& v) {
  switch (v.type()) {
    case Type::Null: out += "null"; break;
    case Type::Int8:
    case Type::Int16:
    case Type::Int32:
    case Type::Int64: out += std::to_string(v.as_int64()); break;
    case Type::Float32:
    case Type::Float64: out += text::format_float(v.as_float64()); break;
    case Type::Vocab: {
      const vocab_t code = v.as_vocab();
      if (code == 0) {
        out += "false";
      } else if (code == vocab("1")) {
        out += "true";
      } else {
        out += '[';
        out += vocab_to_string(code);
        out += ']';
      }
      break;
    }
    case Type::String: append_string(out, v.as_string()); break;
    case Type::Blob: {
      out += '{';
      bool first = true;
      for (const std::uint8_t byte : v.as_blob()) {
        if (!first) out += ' ';
        first = false;
        out += std::to_string(byte);
      }
      out += '}';
      break;
    }
    case Type::List:
      out += '(';
      append_items(out, v.as_list());
      out += ')';
      break;
  }
}

}  // namespace

std::string Value::to_text() const {
  std::string out;
  append_value(out, *this);
  return out;
}

std::string Bottle::to_text() const {
  std::string out;
  append_items(out, *this);
  return out;
}

}  // namespace robogene
