// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Value: construction, ownership of the heap-held types, typed accessors and equality.
#include "robogene/value.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "robogene/bottle.hpp"
#include "robogene/error.hpp"

namespace robogene {

const char* type_name(Type t) noexcept {
  switch (t) {
    case Type::Null: return "null";
    case Type::Int8: return "int8";
    case Type::Int16: return "int16";
    case Type::Int32: return "int32";
    case Type::Int64: return "int64";
    case Type::Float32: return "float32";
    case Type::Float64: return "float64";
    case Type::Vocab: return "vocab";
    case Type::String: return "string";
    case Type::Blob: return "blob";
    case Type::List: return "list";
  }
  return "unknown";
}

namespace {

[[noreturn]] void wrong_type(const char* expected, Type actual) {
  throw Error(std::string("expected ") + expected + ", got " + type_name(actual));
}

// Float to integer the way YARP does (truncation toward zero), but refusing what C++ leaves
// undefined: NaN, infinities and values outside the target range.
template <typename Int>
Int float_to_int(double x, const char* from, const char* to) {
  constexpr double lo = static_cast<double>(std::numeric_limits<Int>::min());
  // 2^(bits-1) is exact as a double; the largest representable Int is below it.
  constexpr double hi_exclusive = -lo;
  if (!(x >= lo && x < hi_exclusive)) {
    throw Error(std::string(from) + " " + std::to_string(x) + " does not fit in " + to);
  }
  return static_cast<Int>(x);
}

}  // namespace

Value::Value() noexcept : type_(Type::Null), i_(0) {}
Value::Value(std::int32_t v) noexcept : type_(Type::Int32), i_(v) {}
Value::Value(std::int64_t v) noexcept : type_(Type::Int64), i_(v) {}
Value::Value(double v) noexcept : type_(Type::Float64), f_(v) {}
Value::Value(const char* s) : type_(Type::String), s_(new std::string(s)) {}
Value::Value(std::string s) : type_(Type::String), s_(new std::string(std::move(s))) {}
Value::Value(std::string_view s) : type_(Type::String), s_(new std::string(s)) {}
Value::Value(Bottle list) : type_(Type::List), l_(new Bottle(std::move(list))) {}

Value Value::int8(std::int8_t v) noexcept {
  Value out;
  out.type_ = Type::Int8;
  out.i_ = v;
  return out;
}

Value Value::int16(std::int16_t v) noexcept {
  Value out;
  out.type_ = Type::Int16;
  out.i_ = v;
  return out;
}

Value Value::int32(std::int32_t v) noexcept { return Value(v); }
Value Value::int64(std::int64_t v) noexcept { return Value(v); }

Value Value::float32(float v) noexcept {
  Value out;
  out.type_ = Type::Float32;
  out.f32_ = v;
  return out;
}

Value Value::float64(double v) noexcept { return Value(v); }

Value Value::vocab(vocab_t code) noexcept {
  Value out;
  out.type_ = Type::Vocab;
  out.i_ = code;
  return out;
}

Value Value::vocab(std::string_view chars) noexcept { return vocab(robogene::vocab(chars)); }

Value Value::string(std::string s) { return Value(std::move(s)); }

Value Value::blob(std::vector<std::uint8_t> bytes) {
  Value out;
  out.b_ = new std::vector<std::uint8_t>(std::move(bytes));
  out.type_ = Type::Blob;
  return out;
}

Value Value::blob(const void* data, std::size_t size) {
  const auto* p = static_cast<const std::uint8_t*>(data);
  return blob(std::vector<std::uint8_t>(p, p + size));
}

Value Value::list(Bottle items) { return Value(std::move(items)); }

Value::Value(const Value& other) : type_(Type::Null), i_(0) { copy_from(other); }

Value& Value::operator=(const Value& other) {
  if (this != &other) {
    Value copy(other);  // copy first: `other` may live inside this value's own list
    destroy();
    move_from(std::move(copy));
  }
  return *this;
}

Value& Value::operator=(Value&& other) noexcept {
  if (this != &other) {
    Value taken(std::move(other));  // `other` may be owned by this value
    destroy();
    move_from(std::move(taken));
  }
  return *this;
}


void Value::destroy() noexcept {
  switch (type_) {
    case Type::String: delete s_; break;
    case Type::Blob: delete b_; break;
    case Type::List: delete l_; break;
    default: break;
  }
  type_ = Type::Null;
  i_ = 0;
}

void Value::copy_from(const Value& other) {
  switch (other.type_) {
    case Type::String: s_ = new std::string(*other.s_); break;
    case Type::Blob: b_ = new std::vector<std::uint8_t>(*other.b_); break;
    case Type::List: l_ = new Bottle(*other.l_); break;
    case Type::Float32: f32_ = other.f32_; break;
    case Type::Float64: f_ = other.f_; break;
    default: i_ = other.i_; break;
  }
  type_ = other.type_;
}

void Value::move_from(Value&& other) noexcept {
  // The union is trivially copyable; taking the pointer member transfers ownership.
  std::memcpy(static_cast<void*>(&i_), static_cast<const void*>(&other.i_), sizeof(i_));
  type_ = other.type_;
  other.type_ = Type::Null;
  other.i_ = 0;
}

bool Value::is_int() const noexcept {
  return type_ == Type::Int8 || type_ == Type::Int16 || type_ == Type::Int32 || type_ == Type::Int64;
}

bool Value::is_float() const noexcept { return type_ == Type::Float32 || type_ == Type::Float64; }

std::int64_t Value::as_int64() const {
  switch (type_) {
    case Type::Int8:
    case Type::Int16:
    case Type::Int32:
    case Type::Int64:
    case Type::Vocab: return i_;
    case Type::Float32: return float_to_int<std::int64_t>(f32_, "float32", "int64");
    case Type::Float64: return float_to_int<std::int64_t>(f_, "float64", "int64");
    default: wrong_type("int64", type_);
  }
}

std::int32_t Value::as_int32() const {
  switch (type_) {
    case Type::Int8:
    case Type::Int16:
    case Type::Int32:
    case Type::Vocab: return static_cast<std::int32_t>(i_);
    case Type::Int64:
      if (i_ < std::numeric_limits<std::int32_t>::min() || i_ > std::numeric_limits<std::int32_t>::max()) {
        throw Error("int64 " + std::to_string(i_) + " does not fit in int32");
      }
      return static_cast<std::int32_t>(i_);
    case Type::Float32: return float_to_int<std::int32_t>(f32_, "float32", "int32");
    case Type::Float64: return float_to_int<std::int32_t>(f_, "float64", "int32");
    default: wrong_type("int32", type_);
  }
}

double Value::as_float64() const {
  switch (type_) {
    case Type::Int8:
    case Type::Int16:
    case Type::Int32:
    case Type::Int64: return static_cast<double>(i_);
    case Type::Float32: return static_cast<double>(f32_);
    case Type::Float64: return f_;
    default: wrong_type("float64", type_);
  }
}

float Value::as_float32() const {
  if (type_ == Type::Float32) return f32_;
  return static_cast<float>(as_float64());
}

vocab_t Value::as_vocab() const {
  switch (type_) {
    case Type::Vocab: return static_cast<vocab_t>(i_);
    case Type::String: return robogene::vocab(*s_);
    case Type::Int8:
    case Type::Int16:
    case Type::Int32: return static_cast<vocab_t>(i_);
    case Type::Int64:
      if (i_ < std::numeric_limits<std::int32_t>::min() || i_ > std::numeric_limits<std::int32_t>::max()) {
        throw Error("int64 " + std::to_string(i_) + " does not fit in a vocab");
      }
      return static_cast<vocab_t>(i_);
    default: wrong_type("vocab", type_);
  }
}

const std::string& Value::as_string() const {
  if (type_ != Type::String) wrong_type("string", type_);
  return *s_;
}

const std::vector<std::uint8_t>& Value::as_blob() const {
  if (type_ != Type::Blob) wrong_type("blob", type_);
  return *b_;
}

std::vector<std::uint8_t>& Value::as_blob() {
  if (type_ != Type::Blob) wrong_type("blob", type_);
  return *b_;
}

const Bottle& Value::as_list() const {
  if (type_ != Type::List) wrong_type("list", type_);
  return *l_;
}

Bottle& Value::as_list() {
  if (type_ != Type::List) wrong_type("list", type_);
  return *l_;
}

bool Value::operator==(const Value& other) const {
  if (type_ != other.type_) return false;
  switch (type_) {
    case Type::Null: return true;
    case Type::Float32: return std::memcmp(&f32_, &other.f32_, sizeof f32_) == 0;
    case Type::Float64: return std::memcmp(&f_, &other.f_, sizeof f_) == 0;
    case Type::String: return *s_ == *other.s_;
    case Type::Blob: return *b_ == *other.b_;
    case Type::List: return *l_ == *other.l_;
    default: return i_ == other.i_;
  }
}

}  // namespace robogene
