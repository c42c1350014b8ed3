// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// One connected TCP socket. Every call either completes or throws robogene::NetworkError naming
// the peer and what failed: EINTR is retried, SIGPIPE never raised (MSG_NOSIGNAL), a timeout is
// an error rather than a hang. TCP_NODELAY is on: port messages are latency-bound.
#pragma once

#include <sys/uio.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

#include "robogene/net/endpoint.hpp"
#include "robogene/net/unique_fd.hpp"

namespace robogene::net {

using Millis = std::chrono::milliseconds;
// A zero timeout means "wait for ever".
constexpr Millis kNoTimeout{0};

class TcpStream {
 public:
  TcpStream() = default;
  // Adopts an already connected socket (from TcpListener::accept).
  explicit TcpStream(UniqueFd fd);

  // Connects to host:port; `timeout` bounds the connect itself.
  static TcpStream connect(const Endpoint& to, Millis timeout = Millis{5000});

  bool is_open() const noexcept { return fd_.valid(); }
  int fd() const noexcept { return fd_.get(); }
  const Endpoint& peer() const noexcept { return peer_; }
  const Endpoint& local() const noexcept { return local_; }
  // "127.0.0.1:40012" for log lines and errors.
  std::string peer_text() const { return peer_.to_string(); }

  // Socket-level timeouts applied to every later read / write (0 = none).
  void set_read_timeout(Millis t);
  void set_write_timeout(Millis t);
  void set_nodelay(bool on);

  // Reads exactly `size` bytes; throws on EOF (naming how many bytes arrived) or error.
  void read_exact(void* data, std::size_t size);
  // Reads what is available (at least 1 byte, at most `size`); returns 0 on orderly EOF.
  std::size_t read_some(void* data, std::size_t size);
  // Waits until a read would not block; false on timeout.
  bool wait_readable(Millis timeout) const;

  void write_all(const void* data, std::size_t size);
  // Gathers all buffers into as few send calls as the kernel allows (one in the usual case).
  void writev_all(iovec* iov, std::size_t count);

  // Wakes any thread blocked in read/write on this socket (they then fail) without closing it.
  void shutdown() noexcept;
  void close() noexcept;

 private:
  [[noreturn]] void fail(const char* doing, int err) const;

  UniqueFd fd_;
  Endpoint peer_;
  Endpoint local_;
};

}  // namespace robogene::net
