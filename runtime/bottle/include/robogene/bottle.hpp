// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Bottle: the paper's one data format, a list of Values with a binary form byte-identical to
// YARP 3 (reference section 1) and a text form a person can type (section 2).
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "robogene/value.hpp"

namespace robogene {

// Limits applied while decoding untrusted input; exceeding one is a ParseError, never a crash.
struct DecodeLimits {
  std::size_t max_depth = 64;                  // nested lists
  std::size_t max_bytes = 512u * 1024u * 1024u;  // whole encoded bottle
  // Items of all lists together: one byte on the wire (an int8 in a typed list) becomes a
  // 16-byte Value, so the bytes alone do not bound what decoding allocates.
  std::size_t max_values = 4u << 20;
};

// Receives a binary encoding piece by piece. Blob bodies arrive through `reference()`, which a
// transport may keep as a pointer (scatter-gather send) instead of copying; the Bottle must then
// outlive the sink's use of the bytes. The default copies.
class ByteSink {
 public:
  virtual ~ByteSink() = default;
  virtual void append(const void* data, std::size_t size) = 0;
  virtual void reference(const void* data, std::size_t size) { append(data, size); }
};

class Bottle {
 public:
  Bottle() = default;
  Bottle(std::initializer_list<Value> items);

  // Text form. Throws ParseError whose position() is the 1-based column of the fault.
  static Bottle from_text(std::string_view text);
  std::string to_text() const;
  // True when `text` holds a whole bottle (balanced quotes, parentheses and braces, no trailing `\`).
  static bool text_is_complete(std::string_view text);

  // Binary form. Throws ParseError whose position() is the byte offset of the fault.
  // The whole input must be consumed; trailing bytes are an error.
  static Bottle from_bytes(const std::uint8_t* data, std::size_t size, const DecodeLimits& limits = {});
  static Bottle from_bytes(const std::vector<std::uint8_t>& bytes, const DecodeLimits& limits = {});
  // Decodes one bottle from the front of `data` and reports how many bytes it used.
  static Bottle from_bytes_prefix(const std::uint8_t* data, std::size_t size, std::size_t* used,
                                  const DecodeLimits& limits = {});
  std::vector<std::uint8_t> to_bytes() const;
  void append_bytes(std::vector<std::uint8_t>& out) const;  // appends the encoding to `out`
  void encode_to(ByteSink& sink) const;                     // the one encoder; the others call it
  std::size_t encoded_size() const;

  std::size_t size() const noexcept { return items_.size(); }
  bool empty() const noexcept { return items_.empty(); }
  void clear() noexcept { items_.clear(); }
  const Value& operator[](std::size_t i) const { return items_[i]; }
  Value& operator[](std::size_t i) { return items_[i]; }
  // Bounds-checked: throws robogene::Error naming the index and size.
  const Value& at(std::size_t i) const;
  // Returns a Null value when i is out of range (YARP's Bottle::get).
  const Value& get(std::size_t i) const noexcept;

  Bottle& add(Value v);
  Bottle& add_list();  // appends an empty nested list and returns it
  void reserve(std::size_t n) { items_.reserve(n); }

  // Property-style lookups, as in YARP's Searchable:
  // find("key") -> the value after "key" in a (key value) nested list, or after "key" at top level;
  // find_group("key") -> the nested list whose first item is "key". Null / nullptr when absent.
  const Value& find(std::string_view key) const noexcept;
  const Bottle* find_group(std::string_view key) const noexcept;

  std::vector<Value>::const_iterator begin() const noexcept { return items_.begin(); }
  std::vector<Value>::const_iterator end() const noexcept { return items_.end(); }
  std::vector<Value>::iterator begin() noexcept { return items_.begin(); }
  std::vector<Value>::iterator end() noexcept { return items_.end(); }

  bool operator==(const Bottle& other) const { return items_ == other.items_; }
  bool operator!=(const Bottle& other) const { return !(*this == other); }

 private:
  std::vector<Value> items_;
};

}  // namespace robogene
