// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Binary decoder for untrusted input. Every count and length is checked against the bytes that
// are actually left before anything is allocated, nesting is bounded, and every failure is a
// ParseError naming the byte offset and what was expected there.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "robogene/bottle.hpp"
#include "robogene/error.hpp"
#include "wire_format.hpp"

namespace robogene {

namespace {

using namespace wire;

std::string hex(std::uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%x", v);
  return buf;
}

// Smallest encoding of one item of a list with subcode `sub` (0: tagged items).
std::size_t min_item_size(std::int32_t sub) noexcept {
  switch (sub) {
    case kTagInt8: return 1;
    case kTagInt16: return 2;
    case kTagInt64:
    case kTagFloat64: return 8;
    case 0: return 4 + 1;  // a tag plus the smallest payload (int8)
    default: return 4;     // int32, vocab, float32, string/blob length
  }
}

class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size, const DecodeLimits& limits)
      : begin_(data), p_(data), end_(data + (size < limits.max_bytes ? size : limits.max_bytes)),
        capped_(size > limits.max_bytes), limits_(limits) {}

  std::size_t offset() const noexcept { return static_cast<std::size_t>(p_ - begin_); }
  std::size_t remaining() const noexcept { return static_cast<std::size_t>(end_ - p_); }

  [[noreturn]] void fail(std::size_t at, const std::string& what) const {
    throw ParseError(at, "byte " + std::to_string(at) + ": " + what);
  }

  // Ensures `n` more bytes exist for a field called `what`.
  void need(std::size_t n, const char* what) const {
    if (n <= remaining()) return;
    if (capped_) {
      fail(offset(), std::string(what) + " runs past the decode limit of " + std::to_string(limits_.max_bytes) + " bytes");
    }
    fail(offset(), std::string("expected ") + std::to_string(n) + " bytes of " + what + ", only " +
                       std::to_string(remaining()) + " remain");
  }

  template <typename T>
  T read(const char* what) {
    need(sizeof(T), what);
    const T v = load_le<T>(p_);
    p_ += sizeof(T);
    return v;
  }

  // A length or count field: the wire holds a signed int32, read unsigned so that a negative
  // value reports as the huge number it would be if trusted.
  std::uint32_t read_length() { return read<std::uint32_t>("length"); }

  const std::uint8_t* take(std::size_t n) {
    const std::uint8_t* at = p_;
    p_ += n;
    return at;
  }

  Bottle top(std::size_t depth) {
    const std::size_t at = offset();
    const auto tag = read<std::int32_t>("bottle tag");
    if ((tag & ~kUnitMask) != kTagList) {
      fail(at, "expected a bottle tag 0x100..0x1ff, got " + hex(static_cast<std::uint32_t>(tag)));
    }
    const std::int32_t sub = tag & kUnitMask;
    if (sub != 0 && !is_scalar_tag(sub)) fail(at, "unknown list item type " + hex(static_cast<std::uint32_t>(sub)) + " in bottle tag");
    return body(sub, depth);
  }

  Bottle body(std::int32_t sub, std::size_t depth) {
    const std::size_t at = offset();
    const std::uint32_t count = read_length();
    const std::size_t min = min_item_size(sub);
    if (count > remaining() / min) {
      if (capped_) fail(at, "list of " + std::to_string(count) + " items runs past the decode limit of " + std::to_string(limits_.max_bytes) + " bytes");
      fail(at, "list count " + std::to_string(count) + " needs at least " + std::to_string(static_cast<std::uint64_t>(count) * min) +
                   " bytes, only " + std::to_string(remaining()) + " remain");
    }
    if (count > values_left_) {
      fail(at, "list of " + std::to_string(count) + " items passes the limit of " +
                   std::to_string(limits_.max_values) + " values in one bottle");
    }
    values_left_ -= count;
    Bottle b;
    b.reserve(count);
    if (fixed_size_items(b, sub, count)) return b;
    for (std::uint32_t i = 0; i < count; ++i) {
      std::int32_t tag = sub;
      std::size_t tag_at = offset();
      if (sub == 0) tag = read<std::int32_t>("item tag");
      b.add(item(tag, tag_at, depth));
    }
    return b;
  }

  Value item(std::int32_t tag, std::size_t tag_at, std::size_t depth) {
    switch (tag) {
      case kTagInt8: return Value::int8(read<std::int8_t>("int8"));
      case kTagInt16: return Value::int16(read<std::int16_t>("int16"));
      case kTagInt32: return Value::int32(read<std::int32_t>("int32"));
      case kTagInt64: return Value::int64(read<std::int64_t>("int64"));
      case kTagVocab: return Value::vocab(read<std::int32_t>("vocab"));
      case kTagFloat32: return Value::float32(read<float>("float32"));
      case kTagFloat64: return Value::float64(read<double>("float64"));
      case kTagString: {
        const std::size_t n = sized_block("string");
        const auto* s = reinterpret_cast<const char*>(take(n));
        // Pre-2015 YARP sent a NUL terminator inside the length; drop one if present.
        return Value::string(std::string(s, (n > 0 && s[n - 1] == '\0') ? n - 1 : n));
      }
      case kTagBlob: {
        const std::size_t n = sized_block("blob");
        return Value::blob(take(n), n);
      }
      case kTagList | kTagDict: {
        enter(depth, tag_at);
        return Value::list(top(depth + 1));  // a dict carries a whole bottle of (key value) pairs
      }
      default: break;
    }
    if ((tag & ~kUnitMask) == kTagList) {
      const std::int32_t sub = tag & kUnitMask;
      if (sub != 0 && !is_scalar_tag(sub)) fail(tag_at, "unknown list item type " + hex(static_cast<std::uint32_t>(sub)) + " in list tag " + hex(static_cast<std::uint32_t>(tag)));
      enter(depth, tag_at);
      return Value::list(body(sub, depth + 1));
    }
    fail(tag_at, "unknown item tag " + hex(static_cast<std::uint32_t>(tag)));
  }

 private:
  // Homogeneous lists of fixed-size numbers (vectors of joint values, control modes) in one tight
  // loop: the count check above already proved that all `count` items are present.
  template <typename T, typename Make>
  void read_all(Bottle& b, std::uint32_t count, Make make) {
    for (std::uint32_t i = 0; i < count; ++i) {
      b.add(make(load_le<T>(p_)));
      p_ += sizeof(T);
    }
  }

  bool fixed_size_items(Bottle& b, std::int32_t sub, std::uint32_t count) {
    switch (sub) {
      case kTagFloat64: read_all<double>(b, count, Value::float64); return true;
      case kTagInt32: read_all<std::int32_t>(b, count, [](std::int32_t v) { return Value::int32(v); }); return true;
      case kTagVocab: read_all<std::int32_t>(b, count, [](std::int32_t v) { return Value::vocab(v); }); return true;
      case kTagInt64: read_all<std::int64_t>(b, count, Value::int64); return true;
      case kTagFloat32: read_all<float>(b, count, Value::float32); return true;
      case kTagInt16: read_all<std::int16_t>(b, count, Value::int16); return true;
      case kTagInt8: read_all<std::int8_t>(b, count, Value::int8); return true;
      default: return false;  // strings, blobs and tagged items are checked one by one
    }
  }

  std::size_t sized_block(const char* what) {
    const std::size_t at = offset();
    const std::uint32_t n = read_length();
    if (n > remaining()) {
      if (capped_) fail(at, std::string(what) + " of " + std::to_string(n) + " bytes runs past the decode limit of " + std::to_string(limits_.max_bytes) + " bytes");
      fail(at, std::string(what) + " length " + std::to_string(n) + " exceeds the " + std::to_string(remaining()) + " bytes remaining");
    }
    return n;
  }

  void enter(std::size_t depth, std::size_t at) const {
    if (depth + 1 > limits_.max_depth) {
      fail(at, "lists nested deeper than the limit of " + std::to_string(limits_.max_depth));
    }
  }

  const std::uint8_t* begin_;
  const std::uint8_t* p_;
  const std::uint8_t* end_;
  bool capped_;
  DecodeLimits limits_;
  std::size_t values_left_ = limits_.max_values;
};

}  // namespace

Bottle Bottle::from_bytes_prefix(const std::uint8_t* data, std::size_t size, std::size_t* used,
                                 const DecodeLimits& limits) {
  Reader r(data, size, limits);
  Bottle b = r.top(0);
  if (used != nullptr) *used = r.offset();
  return b;
}

Bottle Bottle::from_bytes(const std::uint8_t* data, std::size_t size, const DecodeLimits& limits) {
  if (size > limits.max_bytes) {
    throw ParseError(limits.max_bytes, "byte " + std::to_string(limits.max_bytes) + ": input of " + std::to_string(size) +
                                           " bytes exceeds the decode limit of " + std::to_string(limits.max_bytes) + " bytes");
  }
  std::size_t used = 0;
  Bottle b = from_bytes_prefix(data, size, &used, limits);
  if (used != size) {
    const std::size_t extra = size - used;
    throw ParseError(used, "byte " + std::to_string(used) + ": " + std::to_string(extra) +
                               (extra == 1 ? " unexpected byte" : " unexpected bytes") + " after the end of the bottle");
  }
  return b;
}

Bottle Bottle::from_bytes(const std::vector<std::uint8_t>& bytes, const DecodeLimits& limits) {
  return from_bytes(bytes.data(), bytes.size(), limits);
}

}  // namespace robogene
