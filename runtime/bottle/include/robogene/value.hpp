// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Value: one item of a Bottle. The types are YARP 3's (reference section 1.1): int8/16/32/64,
// float32/64, vocab, string, blob, and nested list; dict is decoded into a list of (key value) pairs.
// Null exists only as the answer of a failed lookup and cannot be encoded.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "robogene/vocab.hpp"

namespace robogene {

class Bottle;

enum class Type : std::uint8_t {
  Null,
  Int8,
  Int16,
  Int32,
  Int64,
  Float32,
  Float64,
  Vocab,
  String,
  Blob,
  List,
};

// Name of a type for error messages ("int32", "string", ...).
const char* type_name(Type t) noexcept;

class Value {
 public:
  Value() noexcept;  // Null
  Value(std::int32_t v) noexcept;       // NOLINT: implicit on purpose, Int32
  Value(std::int64_t v) noexcept;       // NOLINT: Int64
  Value(double v) noexcept;             // NOLINT: Float64
  Value(const char* s);                 // NOLINT: String
  Value(std::string s);                 // NOLINT: String
  Value(std::string_view s);            // NOLINT: String
  Value(Bottle list);                   // NOLINT: List

  static Value int8(std::int8_t v) noexcept;
  static Value int16(std::int16_t v) noexcept;
  static Value int32(std::int32_t v) noexcept;
  static Value int64(std::int64_t v) noexcept;
  static Value float32(float v) noexcept;
  static Value float64(double v) noexcept;
  static Value vocab(vocab_t code) noexcept;
  static Value vocab(std::string_view chars) noexcept;  // truncated to 4 chars
  static Value string(std::string s);
  static Value blob(std::vector<std::uint8_t> bytes);
  static Value blob(const void* data, std::size_t size);
  static Value list(Bottle items);

  Value(const Value& other);
  Value(Value&& other) noexcept;
  Value& operator=(const Value& other);
  Value& operator=(Value&& other) noexcept;
  ~Value();

  Type type() const noexcept { return type_; }
  bool is_null() const noexcept { return type_ == Type::Null; }
  bool is_int() const noexcept;    // any integer width
  bool is_float() const noexcept;  // float32 or float64
  bool is_number() const noexcept { return is_int() || is_float(); }
  bool is_vocab() const noexcept { return type_ == Type::Vocab; }
  bool is_string() const noexcept { return type_ == Type::String; }
  bool is_blob() const noexcept { return type_ == Type::Blob; }
  bool is_list() const noexcept { return type_ == Type::List; }

  // Accessors convert between numeric types (as YARP does) and throw robogene::Error naming the
  // expected and actual type otherwise ("expected int32, got string"). Integer accessors also take
  // a vocab (its code, as YARP's asInt32 does) and truncate floats toward zero; a conversion that
  // cannot hold the value (NaN, out of range, int64 -> int32 overflow) throws instead of wrapping.
  // as_vocab() also accepts a string (YARP's asVocab32 does, which is how `get axes` typed at
  // `yarp rpc` matches [get] [axes]) and an integer that fits in 32 bits.
  std::int32_t as_int32() const;
  std::int64_t as_int64() const;
  double as_float64() const;
  float as_float32() const;  // a float32 keeps its exact bits (NaN payload included); others narrow
  vocab_t as_vocab() const;
  const std::string& as_string() const;
  const std::vector<std::uint8_t>& as_blob() const;
  std::vector<std::uint8_t>& as_blob();
  const Bottle& as_list() const;
  Bottle& as_list();

  // Text form of this one value, exactly as YARP 3 renders it inside a bottle.
  std::string to_text() const;

  // Deep, type-sensitive equality; floats compare by bit pattern so NaN round trips compare equal.
  bool operator==(const Value& other) const;
  bool operator!=(const Value& other) const { return !(*this == other); }

 private:
  void destroy() noexcept;
  void copy_from(const Value& other);
  void move_from(Value&& other) noexcept;

  Type type_ = Type::Null;
  union {
    std::int64_t i_;                 // Int8 .. Int64 and Vocab
    double f_;                       // Float64
    float f32_;                      // Float32, kept as float so its bit pattern survives
    std::string* s_;                 // String
    std::vector<std::uint8_t>* b_;   // Blob
    Bottle* l_;                      // List
  };
};

// Moving and destroying are on every hot path (decoding, vectors of values); inline, the scalar
// case costs a few instructions and no call.
inline Value::Value(Value&& other) noexcept : type_(other.type_) {
  std::memcpy(static_cast<void*>(&i_), static_cast<const void*>(&other.i_), sizeof(i_));
  other.type_ = Type::Null;
}

inline Value::~Value() {
  if (type_ == Type::String || type_ == Type::Blob || type_ == Type::List) destroy();
}

}  // namespace robogene
