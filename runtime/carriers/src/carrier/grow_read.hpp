// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Reading n announced bytes into a vector that grows with the bytes that actually arrive, so a
// peer that announces 64 MB and sends 60 bytes makes us hold 64 KB, not 64 MB (private to
// src/carrier). Memory already held (a reused buffer) is filled in one go.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <vector>

#include "robogene/limits.hpp"

namespace robogene::carrier::detail {

inline constexpr std::size_t kFirstGrowth = 64 * 1024;

// Appends n bytes read from `in` (anything with read_exact(void*, size_t)) to the end of `v`.
// Each step at most doubles what was received, so memory stays within twice the bytes that
// came; `budget` (may be null) counts them in the process total before they are read.
template <typename In>
void append_growing(In& in, std::vector<std::uint8_t>& v, std::size_t n, ReceivingBytes* budget) {
  std::size_t done = 0;
  const std::size_t start = v.size();
  while (done < n) {
    std::size_t step = n - done;
    if (v.capacity() < start + n) step = std::min(step, std::max(kFirstGrowth, start + done));
    if (budget) budget->add(step);
    v.resize(start + done + step);
    in.read_exact(v.data() + start + done, step);
    done += step;
  }
}

// Gives a message's (or reply's) bytes back to the process total when it is complete or fails.
// When it fails, `buffer` (if given), which those bytes were read into, is freed as well: else
// a failed connection would keep the memory after its share of the total had been given back,
// and others could take that share again.
class ReleaseOnExit {
 public:
  explicit ReleaseOnExit(ReceivingBytes& budget, std::vector<std::uint8_t>* buffer = nullptr)
      : budget_(budget), buffer_(buffer), exceptions_(std::uncaught_exceptions()) {}
  ~ReleaseOnExit() {
    budget_.release();
    if (buffer_ && std::uncaught_exceptions() > exceptions_) std::vector<std::uint8_t>().swap(*buffer_);
  }
  ReleaseOnExit(const ReleaseOnExit&) = delete;
  ReleaseOnExit& operator=(const ReleaseOnExit&) = delete;

 private:
  ReceivingBytes& budget_;
  std::vector<std::uint8_t>* buffer_;
  int exceptions_;
};

}  // namespace robogene::carrier::detail
