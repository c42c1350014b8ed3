// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/carrier/encoded_payload.hpp"

#include <cstring>

namespace robogene::carrier {

void EncodedPayload::clear() noexcept {
  owned_.clear();
  blocks_.clear();
  total_ = 0;
}

void EncodedPayload::encode(const Bottle& b) {
  clear();
  b.encode_to(*this);
}

void EncodedPayload::append(const void* data, std::size_t size) {
  if (size == 0) return;
  std::size_t at = owned_.size();
  owned_.resize(at + size);
  std::memcpy(owned_.data() + at, data, size);
  if (!blocks_.empty() && blocks_.back().external == nullptr) {
    blocks_.back().size += size;
  } else {
    blocks_.push_back(Block{nullptr, at, size});
  }
  total_ += size;
}

void EncodedPayload::reference(const void* data, std::size_t size) {
  if (size == 0) return;
  // Small bodies are cheaper to copy than to give their own iovec.
  if (size < 4096) {
    append(data, size);
    return;
  }
  blocks_.push_back(Block{static_cast<const std::uint8_t*>(data), 0, size});
  total_ += size;
}

void EncodedPayload::append_iovecs(std::vector<iovec>& out) const {
  for (const Block& b : blocks_) {
    const std::uint8_t* p = b.external ? b.external : owned_.data() + b.offset;
    out.push_back(iovec{const_cast<std::uint8_t*>(p), b.size});
  }
}

std::vector<std::uint8_t> EncodedPayload::flatten() const {
  std::vector<std::uint8_t> out;
  out.reserve(total_);
  for (const Block& b : blocks_) {
    const std::uint8_t* p = b.external ? b.external : owned_.data() + b.offset;
    out.insert(out.end(), p, p + b.size);
  }
  return out;
}

}  // namespace robogene::carrier
