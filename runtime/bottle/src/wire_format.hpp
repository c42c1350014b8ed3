// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// YARP 3 binary bottle constants (reference section 1.1) and little-endian load/store helpers,
// shared by the binary encoder and decoder only.
#pragma once

#include <cstdint>
#include <cstring>

#include "robogene/value.hpp"

namespace robogene::wire {

constexpr std::int32_t kTagInt8 = 0x20;
constexpr std::int32_t kTagInt16 = 0x40;
constexpr std::int32_t kTagInt32 = 0x01;
constexpr std::int32_t kTagInt64 = 0x11;
constexpr std::int32_t kTagVocab = 0x09;
constexpr std::int32_t kTagFloat32 = 0x80;
constexpr std::int32_t kTagFloat64 = 0x0a;
constexpr std::int32_t kTagString = 0x04;
constexpr std::int32_t kTagBlob = 0x0c;
constexpr std::int32_t kTagList = 0x100;
constexpr std::int32_t kTagDict = 0x200;
constexpr std::int32_t kUnitMask = 0xff;

// The item tag of a scalar type (0 for List and Null, which have no scalar tag).
constexpr std::int32_t scalar_tag(Type t) noexcept {
  switch (t) {
    case Type::Int8: return kTagInt8;
    case Type::Int16: return kTagInt16;
    case Type::Int32: return kTagInt32;
    case Type::Int64: return kTagInt64;
    case Type::Float32: return kTagFloat32;
    case Type::Float64: return kTagFloat64;
    case Type::Vocab: return kTagVocab;
    case Type::String: return kTagString;
    case Type::Blob: return kTagBlob;
    case Type::Null:
    case Type::List: return 0;
  }
  return 0;
}

constexpr bool is_scalar_tag(std::int32_t tag) noexcept {
  switch (tag) {
    case kTagInt8: case kTagInt16: case kTagInt32: case kTagInt64: case kTagVocab:
    case kTagFloat32: case kTagFloat64: case kTagString: case kTagBlob: return true;
    default: return false;
  }
}

// Wire integers are little-endian whatever the host is.
template <typename T>
inline void store_le(std::uint8_t* out, T value) noexcept {
  static_assert(sizeof(T) <= 8);
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof(T));  // the low bytes on a little-endian host
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
  std::memcpy(out, &bits, sizeof(T));
#else
  if constexpr (sizeof(T) == 1) { out[0] = static_cast<std::uint8_t>(bits); return; }
  std::uint64_t v = 0;
  if constexpr (sizeof(T) == 2) { std::uint16_t x; std::memcpy(&x, &value, 2); v = x; }
  if constexpr (sizeof(T) == 4) { std::uint32_t x; std::memcpy(&x, &value, 4); v = x; }
  if constexpr (sizeof(T) == 8) { std::memcpy(&v, &value, 8); }
  for (std::size_t i = 0; i < sizeof(T); ++i) out[i] = static_cast<std::uint8_t>(v >> (8 * i));
#endif
}

template <typename T>
inline T load_le(const std::uint8_t* in) noexcept {
  static_assert(sizeof(T) <= 8);
  T value;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
  std::memcpy(&value, in, sizeof(T));
#else
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i) v |= static_cast<std::uint64_t>(in[i]) << (8 * i);
  if constexpr (sizeof(T) == 1) { std::uint8_t x = static_cast<std::uint8_t>(v); std::memcpy(&value, &x, 1); }
  if constexpr (sizeof(T) == 2) { std::uint16_t x = static_cast<std::uint16_t>(v); std::memcpy(&value, &x, 2); }
  if constexpr (sizeof(T) == 4) { std::uint32_t x = static_cast<std::uint32_t>(v); std::memcpy(&value, &x, 4); }
  if constexpr (sizeof(T) == 8) { std::memcpy(&value, &v, 8); }
#endif
  return value;
}

}  // namespace robogene::wire
