// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A Bottle's binary encoding as a list of blocks ready for writev: small items are copied into
// one owned buffer, blob bodies stay where they are (ByteSink::reference). A 640x480 image thus
// goes out as [header block][921600-byte pixels] with no copy of the pixels, exactly the block
// split YARP itself produces. Reusable: clear() keeps the capacity.
#pragma once

#include <sys/uio.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "robogene/bottle.hpp"

namespace robogene::carrier {

class EncodedPayload final : public ByteSink {
 public:
  void clear() noexcept;
  void encode(const Bottle& b);
  void append(const void* data, std::size_t size) override;
  void reference(const void* data, std::size_t size) override;

  std::size_t size() const noexcept { return total_; }
  std::size_t block_count() const noexcept { return blocks_.size(); }
  std::size_t block_size(std::size_t i) const noexcept { return blocks_[i].size; }
  // Appends one iovec per block (valid until the next change to this payload).
  void append_iovecs(std::vector<iovec>& out) const;
  // Copies every block into one contiguous buffer (for datagrams and tests).
  std::vector<std::uint8_t> flatten() const;

 private:
  struct Block {
    const std::uint8_t* external;  // nullptr: bytes live in owned_ at `offset`
    std::size_t offset;
    std::size_t size;
  };
  std::vector<std::uint8_t> owned_;
  std::vector<Block> blocks_;
  std::size_t total_ = 0;
};

}  // namespace robogene::carrier
