// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Template body of read_payload_from (included by payload_reader.hpp): any source with
// read_exact(void*, size_t) — a tcp StreamReader, a shared-memory ring.
#pragma once

#include <string>

#include "grow_read.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/limits.hpp"

namespace robogene::carrier::detail {

inline constexpr std::int32_t kPayloadList = 0x100;
inline constexpr std::int32_t kPayloadDict = 0x200;
inline constexpr std::int32_t kPayloadBlob = 12;

// Thrown (and caught below) when the bytes stop looking like a Bottle we can walk.
struct NotWalkable {};

template <typename In>
class PayloadWalker {
 public:
  PayloadWalker(In& in, std::size_t size, InboundMessage& m, ReceivingBytes& budget)
      : in_(in), left_(size), m_(m), budget_(budget) {}

  void walk() {
    std::int32_t tag = int32();
    if ((tag & kPayloadList) == 0 || (tag & kPayloadDict)) throw NotWalkable{};
    body(tag & 0xff, 0);
  }

  void read_rest() {
    append_growing(in_, m_.payload, left_, &budget_);
    left_ = 0;
  }

 private:
  void body(std::int32_t sub, int depth) {
    if (depth > 64) throw NotWalkable{};
    std::int32_t count = int32();
    if (count < 0) throw NotWalkable{};
    for (std::int32_t i = 0; i < count; ++i) item(sub ? sub : int32(), depth);
  }

  void item(std::int32_t tag, int depth) {
    if (tag & kPayloadDict) throw NotWalkable{};
    if (tag & kPayloadList) {
      body(tag & 0xff, depth + 1);
      return;
    }
    switch (tag) {
      case 32: copy(1); break;
      case 64: copy(2); break;
      case 1: case 9: case 128: copy(4); break;
      case 17: case 10: copy(8); break;
      case 4: {
        std::int32_t len = int32();
        if (len < 0) throw NotWalkable{};
        copy(static_cast<std::size_t>(len));
        break;
      }
      case kPayloadBlob: {
        std::size_t len_at = m_.payload.size();
        std::int32_t len = int32();
        if (len < 0 || static_cast<std::size_t>(len) > left_) throw NotWalkable{};
        auto n = static_cast<std::size_t>(len);
        if (n >= kDetachBlobsFrom) {
          put_int32(m_.payload.data() + len_at, 0);
          std::vector<std::uint8_t> body = buffer(n);
          left_ -= n;
          m_.detached_blobs.push_back(std::move(body));
          m_.detached_blob_ordinals.push_back(blob_ordinal_);
        } else {
          copy(n);
        }
        ++blob_ordinal_;
        break;
      }
      default:
        throw NotWalkable{};
    }
  }

  // The next n bytes in a buffer of their own: a spare one when it is big enough (shrinking
  // never clears memory), else one that grows as the bytes arrive.
  std::vector<std::uint8_t> buffer(std::size_t n) {
    for (auto it = m_.spare_blobs.begin(); it != m_.spare_blobs.end(); ++it) {
      if (it->size() >= n) {
        std::vector<std::uint8_t> v = std::move(*it);
        m_.spare_blobs.erase(it);
        v.resize(n);
        budget_.add(n);
        in_.read_exact(v.data(), n);
        return v;
      }
    }
    std::vector<std::uint8_t> v;
    append_growing(in_, v, n, &budget_);
    return v;
  }

  std::int32_t int32() {
    std::size_t at = m_.payload.size();
    copy(4);
    return get_int32(m_.payload.data() + at);
  }

  void copy(std::size_t n) {
    if (n > left_) throw NotWalkable{};
    append_growing(in_, m_.payload, n, &budget_);
    left_ -= n;
  }

  In& in_;
  std::size_t left_;
  InboundMessage& m_;
  ReceivingBytes& budget_;
  std::size_t blob_ordinal_ = 0;
};

template <typename In>
void read_payload_from(In& in, std::size_t size, InboundMessage& m) {
  m.detached_blobs.clear();
  m.detached_blob_ordinals.clear();
  if (size < kDetachBlobsFrom) {
    m.payload.resize(size);
    if (size) in.read_exact(m.payload.data(), size);
    return;
  }
  m.payload.clear();
  // Only big messages count in the process total: smaller ones are bounded per connection.
  ReceivingBytes budget("a message of " + std::to_string(size) + " bytes");
  PayloadWalker<In> w(in, size, m, budget);
  try {
    w.walk();
  } catch (const NotWalkable&) {
    // Not a Bottle we can walk: keep what was cut out, read the rest as bytes. The decoder
    // will report the problem (or the owner reads raw bytes); the stream stays in step.
  }
  w.read_rest();
}

}  // namespace robogene::carrier::detail
