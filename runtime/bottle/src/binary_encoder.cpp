// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The one binary encoder (reference sections 1.2-1.5), byte-identical to YARP 3 including its
// homogeneous-list rule: a list whose items all have the same scalar type is written with tag
// 0x100|T and no per-item tags. Small fields are gathered in a local buffer so the sink sees one
// virtual call per chunk, never per byte; blob bodies are handed over with ByteSink::reference.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "robogene/bottle.hpp"
#include "robogene/error.hpp"
#include "wire_format.hpp"

namespace robogene {

namespace {

using namespace wire;

// YARP's subCoder: the shared scalar tag of all items, or 0 (mixed, empty, or lists).
std::int32_t subcode(const Bottle& b) noexcept {
  if (b.empty()) return 0;
  const Type first = b[0].type();
  const std::int32_t tag = scalar_tag(first);
  if (tag == 0) return 0;
  for (const Value& v : b) {
    if (v.type() != first) return 0;
  }
  return tag;
}

std::int32_t checked_length(std::size_t n, const char* what) {
  if (n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    throw Error(std::string(what) + " of " + std::to_string(n) + " exceeds the 2147483647 a bottle can carry");
  }
  return static_cast<std::int32_t>(n);
}

class ChunkWriter {
 public:
  explicit ChunkWriter(ByteSink& sink) : sink_(sink) {}
  ChunkWriter(const ChunkWriter&) = delete;
  ChunkWriter& operator=(const ChunkWriter&) = delete;

  template <typename T>
  void put(T v) {
    if (used_ + sizeof(T) > sizeof buf_) flush();
    store_le(buf_ + used_, v);
    used_ += sizeof(T);
  }

  void copy(const void* data, std::size_t size) {
    if (size <= sizeof buf_ - used_) {
      std::memcpy(buf_ + used_, data, size);
      used_ += size;
      return;
    }
    flush();
    sink_.append(data, size);
  }

  void reference(const void* data, std::size_t size) {
    flush();
    sink_.reference(data, size);
  }

  void flush() {
    if (used_ != 0) sink_.append(buf_, used_);
    used_ = 0;
  }

 private:
  ByteSink& sink_;
  std::size_t used_ = 0;
  std::uint8_t buf_[512];
};

void write_body(ChunkWriter& w, const Bottle& b, std::int32_t sub);

void write_payload(ChunkWriter& w, const Value& v) {
  switch (v.type()) {
    case Type::Int8: w.put(static_cast<std::int8_t>(v.as_int64())); break;
    case Type::Int16: w.put(static_cast<std::int16_t>(v.as_int64())); break;
    case Type::Int32: w.put(static_cast<std::int32_t>(v.as_int64())); break;
    case Type::Int64: w.put(v.as_int64()); break;
    case Type::Vocab: w.put(v.as_vocab()); break;
    case Type::Float32: w.put(v.as_float32()); break;
    case Type::Float64: w.put(v.as_float64()); break;
    case Type::String: {
      const std::string& s = v.as_string();
      w.put(checked_length(s.size(), "string length"));
      w.copy(s.data(), s.size());  // no NUL terminator, as YARP >= 2.3.64
      break;
    }
    case Type::Blob: {
      const auto& bytes = v.as_blob();
      w.put(checked_length(bytes.size(), "blob length"));
      if (!bytes.empty()) w.reference(bytes.data(), bytes.size());
      break;
    }
    case Type::List: {
      const Bottle& child = v.as_list();
      write_body(w, child, subcode(child));
      break;
    }
    case Type::Null: throw Error("a null value cannot be encoded (null only marks a failed lookup)");
  }
}

std::int32_t item_tag(const Value& v) {
  if (v.is_list()) return kTagList | subcode(v.as_list());
  if (v.is_null()) throw Error("a null value cannot be encoded (null only marks a failed lookup)");
  return scalar_tag(v.type());
}

void write_body(ChunkWriter& w, const Bottle& b, std::int32_t sub) {
  w.put(checked_length(b.size(), "item count"));
  // Vectors of joint values are the common stream: one tight loop, no per-item dispatch.
  if (sub == kTagFloat64) {
    for (const Value& v : b) w.put(v.as_float64());
    return;
  }
  if (sub == kTagInt32) {
    for (const Value& v : b) w.put(v.as_int32());
    return;
  }
  for (const Value& v : b) {
    if (sub == 0) w.put(item_tag(v));
    write_payload(w, v);
  }
}

std::size_t payload_size(const Value& v);

std::size_t body_size(const Bottle& b, std::int32_t sub) {
  if (sub == kTagFloat64 || sub == kTagInt64) return 4 + 8 * b.size();
  if (sub == kTagInt32 || sub == kTagVocab || sub == kTagFloat32) return 4 + 4 * b.size();
  std::size_t n = 4 + (sub == 0 ? 4 * b.size() : 0);
  for (const Value& v : b) n += payload_size(v);
  return n;
}

std::size_t payload_size(const Value& v) {
  switch (v.type()) {
    case Type::Int8: return 1;
    case Type::Int16: return 2;
    case Type::Int32:
    case Type::Vocab:
    case Type::Float32: return 4;
    case Type::Int64:
    case Type::Float64: return 8;
    case Type::String: return 4 + v.as_string().size();
    case Type::Blob: return 4 + v.as_blob().size();
    case Type::List: return body_size(v.as_list(), subcode(v.as_list()));
    case Type::Null: break;
  }
  throw Error("a null value cannot be encoded (null only marks a failed lookup)");
}

class VectorSink final : public ByteSink {
 public:
  explicit VectorSink(std::vector<std::uint8_t>& out) : out_(out) {}
  void append(const void* data, std::size_t size) override {
    const auto* p = static_cast<const std::uint8_t*>(data);
    out_.insert(out_.end(), p, p + size);
  }

 private:
  std::vector<std::uint8_t>& out_;
};

}  // namespace

void Bottle::encode_to(ByteSink& sink) const {
  ChunkWriter w(sink);
  const std::int32_t sub = subcode(*this);
  w.put(kTagList | sub);
  write_body(w, *this, sub);
  w.flush();
}

std::size_t Bottle::encoded_size() const { return 4 + body_size(*this, subcode(*this)); }

void Bottle::append_bytes(std::vector<std::uint8_t>& out) const {
  out.reserve(out.size() + encoded_size());
  VectorSink sink(out);
  encode_to(sink);
}

std::vector<std::uint8_t> Bottle::to_bytes() const {
  std::vector<std::uint8_t> out;
  append_bytes(out);
  return out;
}

}  // namespace robogene
