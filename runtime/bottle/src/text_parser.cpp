// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Text parsing (reference section 2). On well-formed input the result is what YARP 3's
// BottleImpl::fromString + smartAdd produce; where YARP silently swallows malformed input
// (unbalanced quotes or brackets, a stray ')', a blob byte of 300) we stop with a ParseError that
// carries the 1-based column. The grammar is written down in docs/protocol/bottle.md.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "number_text.hpp"
#include "robogene/bottle.hpp"
#include "robogene/text_completeness.hpp"
#include "robogene/error.hpp"

namespace robogene {

namespace {

bool is_separator(char c) noexcept { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ','; }

// Printable form of one character for messages.
std::string shown(char c) {
  if (c == '\n') return "'\\n'";
  if (c == '\r') return "'\\r'";
  if (c == '\t') return "'\\t'";
  if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
    return "byte " + std::to_string(static_cast<unsigned char>(c));
  }
  return std::string("'") + c + "'";
}

// The text with backslash-newline continuations removed (YARP joins such lines with nothing in
// between), plus where each remaining character came from, for error columns.
struct Source {
  std::string text;
  std::vector<std::size_t> origin;  // empty when nothing was removed: origin is the identity
  std::string_view original;

  explicit Source(std::string_view in) : original(in) {
    if (in.find("\\\n") == std::string_view::npos && in.find("\\\r\n") == std::string_view::npos) {
      text.assign(in);
      return;
    }
    text.reserve(in.size());
    origin.reserve(in.size());
    for (std::size_t i = 0; i < in.size(); ++i) {
      if (in[i] == '\\' && i + 1 < in.size()) {
        if (in[i + 1] == '\n') { ++i; continue; }
        if (in[i + 1] == '\r' && i + 2 < in.size() && in[i + 2] == '\n') { i += 2; continue; }
        text += in[i];
        origin.push_back(i);
        ++i;  // keep an escape pair together: `\\` followed by a newline is not a continuation
      }
      text += in[i];
      origin.push_back(i);
    }
  }

  std::size_t original_index(std::size_t i) const {
    if (origin.empty()) return i;
    return i < origin.size() ? origin[i] : original.size();
  }
};

class Parser {
 public:
  explicit Parser(std::string_view text) : src_(text), s_(src_.text) {}

  Bottle parse() {
    Bottle out;
    items(out, std::string::npos);
    return out;
  }

 private:
  [[noreturn]] void fail(std::size_t at, const std::string& what) const {
    const std::size_t index = src_.original_index(at);
    const std::string_view text = src_.original;
    const std::size_t line_start = text.rfind('\n', index == 0 ? 0 : index - 1);
    std::string where;
    if (text.find('\n') == std::string_view::npos || index == 0) {
      where = "column " + std::to_string(index + 1);
    } else {
      std::size_t line = 1;
      for (std::size_t i = 0; i < index && i < text.size(); ++i) line += text[i] == '\n' ? 1 : 0;
      const std::size_t col = line_start == std::string_view::npos ? index + 1 : index - line_start;
      where = "line " + std::to_string(line) + " column " + std::to_string(col) + " (character " +
              std::to_string(index + 1) + ")";
    }
    throw ParseError(index + 1, where + ": " + what);
  }

  bool at_end() const noexcept { return pos_ >= s_.size(); }
  char peek() const noexcept { return s_[pos_]; }

  void skip_separators() {
    while (!at_end() && is_separator(peek())) ++pos_;
  }

  // Items up to the end of text (open == npos) or up to the ')' matching the '(' at `open`.
  void items(Bottle& out, std::size_t open) {
    for (;;) {
      skip_separators();
      if (at_end()) {
        if (open != std::string::npos) fail(open, "'(' has no matching ')'");
        return;
      }
      const char c = peek();
      if (c == ')') {
        if (open == std::string::npos) fail(pos_, "')' has no matching '('");
        ++pos_;
        return;
      }
      out.add(item());
      if (!at_end() && !is_separator(peek()) && peek() != ')') {
        fail(pos_, "unexpected " + shown(peek()) + " right after an item; separate items with a space");
      }
    }
  }

  Value item() {
    const std::size_t start = pos_;
    switch (peek()) {
      case '(': {
        if (++depth_ > DecodeLimits{}.max_depth) {
          fail(start, "lists nested deeper than the limit of " + std::to_string(DecodeLimits{}.max_depth));
        }
        ++pos_;
        Bottle nested;
        items(nested, start);
        --depth_;
        return Value::list(std::move(nested));
      }
      case '"': return quoted();
      case '[': return vocab_item();
      case '{': return blob();
      case '}': fail(pos_, "'}' has no matching '{'");
      default: return word();
    }
  }

  Value quoted() {
    const std::size_t open = pos_++;
    std::string out;
    while (!at_end()) {
      const char c = s_[pos_++];
      if (c == '"') return Value::string(std::move(out));
      if (c == '\\') {
        if (at_end()) break;
        out += unescape(s_[pos_++]);
      } else {
        out += c;
      }
    }
    fail(open, "string has no closing '\"'");
  }

  // YARP's unescaping (StoreString::fromStringNested): \n \r \0 are control characters, a
  // backslash before anything else stands for that character.
  static char unescape(char c) noexcept {
    switch (c) {
      case 'n': return '\n';
      case 'r': return '\r';
      case '0': return '\0';
      default: return c;
    }
  }

  Value vocab_item() {
    const std::size_t open = pos_++;
    std::string chars;
    while (!at_end() && peek() != ']' && !is_separator(peek())) {
      // Escapes as in strings ("[a\0b]"): how the writer keeps NULs and separators in a vocab.
      if (peek() == '\\' && pos_ + 1 < s_.size()) {
        chars += unescape(s_[pos_ + 1]);
        pos_ += 2;
      } else {
        chars += s_[pos_++];
      }
    }
    if (at_end() || peek() != ']') fail(open, "'[' has no closing ']' (a vocab is up to four characters without spaces)");
    ++pos_;
    return Value::vocab(chars);  // YARP keeps the first four characters
  }

  Value blob() {
    const std::size_t open = pos_++;
    std::vector<std::uint8_t> bytes;
    for (;;) {
      skip_separators();
      if (at_end()) fail(open, "'{' has no matching '}'");
      if (peek() == '}') {
        ++pos_;
        return Value::blob(std::move(bytes));
      }
      const std::size_t start = pos_;
      while (!at_end() && !is_separator(peek()) && peek() != '}') ++pos_;
      const std::string_view token(s_.data() + start, pos_ - start);
      if (text::classify_number(token) != text::NumberKind::Integer) {
        fail(start, "blob byte '" + std::string(token) + "' is not an integer 0..255");
      }
      const Value v = text::parse_integer(token);
      const std::int64_t b = v.as_int64();
      if (b < 0 || b > 255) fail(start, "blob byte " + std::string(token) + " is outside 0..255");
      bytes.push_back(static_cast<std::uint8_t>(b));
    }
  }

  Value word() {
    const std::size_t start = pos_;
    bool escaped = false;
    while (!at_end()) {
      const char c = peek();
      if (is_separator(c) || c == ')' || c == '(' || c == '"' || c == '{' || c == '}') break;
      if (c == '\\') {
        if (pos_ + 1 >= s_.size()) fail(pos_, "text ends with a '\\' that continues nothing");
        escaped = true;
        pos_ += 2;
        continue;
      }
      ++pos_;
    }
    const std::string_view token(s_.data() + start, pos_ - start);
    if (!escaped) {
      if (token == "null") return Value::vocab("null");
      if (token == "true") return Value::vocab(vocab("1"));
      if (token == "false") return Value::vocab(vocab_t{0});
      switch (text::classify_number(token)) {
        case text::NumberKind::Integer: return text::parse_integer(token);
        case text::NumberKind::Float: return Value::float64(text::parse_float(token));
        case text::NumberKind::NotANumber: return Value::string(std::string(token));
      }
    }
    std::string out;
    for (std::size_t i = 0; i < token.size(); ++i) {
      out += token[i] == '\\' ? unescape(token[++i]) : token[i];
    }
    return Value::string(std::move(out));
  }

  Source src_;
  const std::string& s_;
  std::size_t pos_ = 0;
  std::size_t depth_ = 0;  // bounded like the binary decoder's, so hostile text cannot exhaust the stack
};

}  // namespace

Bottle Bottle::from_text(std::string_view text) { return Parser(text).parse(); }

void TextCompleteness::feed(std::string_view text) noexcept {
  for (const char c : text) {
    if (escape_) {
      escape_ = false;
      continue;
    }
    if (c == '\\') {
      escape_ = true;
      continue;
    }
    if (c == '"') {
      quoted_ = !quoted_;
      continue;
    }
    if (quoted_) continue;
    if (c == '(') ++parens_;
    if (c == ')') --parens_;
    if (c == '{') ++braces_;
    if (c == '}') --braces_;
  }
}

bool Bottle::text_is_complete(std::string_view text) {
  // YARP's isComplete plus its line-continuation rule; one trailing line end is not looked at.
  std::size_t end = text.size();
  if (end > 0 && text[end - 1] == '\n') --end;
  if (end > 0 && text[end - 1] == '\r') --end;
  TextCompleteness scan;
  scan.feed(text.substr(0, end));
  return scan.complete();
}

}  // namespace robogene
