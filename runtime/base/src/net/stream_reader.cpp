// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/net/stream_reader.hpp"

#include <algorithm>
#include <cstring>

#include "robogene/error.hpp"

namespace robogene::net {

bool StreamReader::fill() {
  if (begin_ == end_) begin_ = end_ = 0;
  if (end_ == buffer_.size()) {
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  std::size_t n = stream_->read_some(buffer_.data() + end_, buffer_.size() - end_);
  end_ += n;
  return n > 0;
}

void StreamReader::read_exact(void* data, std::size_t size) {
  auto* out = static_cast<std::uint8_t*>(data);
  std::size_t from_buffer = std::min(size, buffered());
  if (from_buffer) std::memcpy(out, buffer_.data() + begin_, from_buffer);
  begin_ += from_buffer;
  consumed_ += from_buffer;
  std::size_t left = size - from_buffer;
  if (left == 0) return;
  if (left >= buffer_.size() / 2) {
    try {
      stream_->read_exact(out + from_buffer, left);
    } catch (const NetworkError&) {
      throw NetworkError("peer " + stream_->peer_text() + " closed or failed with " +
                         std::to_string(left) + " of " + std::to_string(size) +
                         " expected bytes missing");
    }
    consumed_ += left;
    return;
  }
  while (buffered() < left) {
    if (!fill()) {
      throw NetworkError("peer " + stream_->peer_text() + " closed the connection after " +
                         std::to_string(from_buffer + buffered()) + " of " + std::to_string(size) +
                         " expected bytes");
    }
  }
  std::memcpy(out + from_buffer, buffer_.data() + begin_, left);
  begin_ += left;
  consumed_ += left;
}

std::string StreamReader::read_line(std::size_t max_length) {
  std::string line;
  for (;;) {
    auto* start = buffer_.data() + begin_;
    auto* nl = static_cast<std::uint8_t*>(std::memchr(start, '\n', buffered()));
    std::size_t take = nl ? static_cast<std::size_t>(nl - start) + 1 : buffered();
    for (std::size_t i = 0; i < take; ++i) {
      char c = static_cast<char>(start[i]);
      if (c != '\r' && c != '\n') line.push_back(c);
    }
    begin_ += take;
    consumed_ += take;
    if (line.size() > max_length) {
      throw NetworkError("peer " + stream_->peer_text() + " sent a line longer than " +
                         std::to_string(max_length) + " bytes without a newline");
    }
    if (nl) return line;
    if (!fill()) {
      throw NetworkError("peer " + stream_->peer_text() + " closed the connection in the middle "
                         "of a text line (" + std::to_string(line.size()) + " bytes read)");
    }
  }
}

bool StreamReader::wait_for_data() {
  if (buffered() > 0) return true;
  return fill();
}

}  // namespace robogene::net
