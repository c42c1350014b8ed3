// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A deadline for a whole acceptor handshake (private to src/carrier). Socket timeouts bound each
// read; a peer dripping one byte just inside that bound could hold the connection (and its
// thread) for ever. While a HandshakeDeadline lives, one process-wide timer thread shuts the
// socket down when the deadline passes, which fails the handshake's next read or write.
#pragma once

#include <chrono>

namespace robogene::carrier::detail {

class HandshakeDeadline {
 public:
  // Watches the socket `fd` (a duplicate is kept, so closing `fd` early is safe).
  HandshakeDeadline(int fd, std::chrono::milliseconds within);
  ~HandshakeDeadline();
  HandshakeDeadline(const HandshakeDeadline&) = delete;
  HandshakeDeadline& operator=(const HandshakeDeadline&) = delete;
  // Whether the deadline passed (and the socket was shut down).
  bool expired() const;

 private:
  int dup_fd_ = -1;
  unsigned long id_ = 0;
};

}  // namespace robogene::carrier::detail
