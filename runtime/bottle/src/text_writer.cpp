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

// "[set]" as YARP writes it; the bytes YARP's form would lose or misread (a NUL before the
// last character, a separator, ']' or '\\', and the quotes and brackets that make a text
// carrier wait for the rest of a multi-line bottle) are escaped as in strings, so the text
// reads back as the same code.
void append_vocab(std::string& out, vocab_t code) {
  const auto bits = static_cast<std::uint32_t>(code);
  int used = 4;
  while (used > 0 && ((bits >> (8 * (used - 1))) & 0xffu) == 0) --used;  // trailing NULs: padding
  out += '[';
  for (int i = 0; i < used; ++i) {
    const char c = static_cast<char>((bits >> (8 * i)) & 0xffu);
    switch (c) {
      case '\0': out += "\\0"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\\': case ']': case ' ': case '\t': case ',': case '"': case '(': case ')': case '{': case '}':
        out += '\\';
        out += c;
        break;
      default: out += c;
    }
  }
  out += ']';
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
        append_vocab(out, code);
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
