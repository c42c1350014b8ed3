// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Buffered reading from a TcpStream: text carriers read lines, binary carriers read exact
// blocks. Large reads go straight into the caller's memory once the buffer is drained.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "robogene/net/tcp_stream.hpp"

namespace robogene::net {

class StreamReader {
 public:
  explicit StreamReader(TcpStream& stream) : stream_(&stream) {}

  void read_exact(void* data, std::size_t size);
  // Reads up to and including '\n'; returns the line without "\n" and with any "\r" dropped
  // (as YARP's readLine does). Throws NetworkError at EOF, or if `max_length` bytes pass without
  // a newline (naming the limit), so a peer cannot make us buffer without bound.
  std::string read_line(std::size_t max_length);
  // True when a whole line is not needed: EOF before the first byte of a message.
  // Returns false at orderly EOF, true when at least one byte is available.
  bool wait_for_data();
  // Bytes already buffered (read from the socket but not consumed).
  std::size_t buffered() const noexcept { return end_ - begin_; }
  // Bytes consumed since construction (for error offsets).
  std::uint64_t consumed() const noexcept { return consumed_; }
  TcpStream& stream() noexcept { return *stream_; }

 private:
  bool fill();  // false on EOF

  TcpStream* stream_;
  std::vector<std::uint8_t> buffer_ = std::vector<std::uint8_t>(16384);
  std::size_t begin_ = 0;
  std::size_t end_ = 0;
  std::uint64_t consumed_ = 0;
};

}  // namespace robogene::net
