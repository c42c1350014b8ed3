// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A listening TCP socket on a chosen or ephemeral (port 0) port. accept() can be interrupted
// from another thread, which is how a port's server thread is stopped cleanly.
#pragma once

#include <optional>

#include "robogene/net/endpoint.hpp"
#include "robogene/net/tcp_stream.hpp"
#include "robogene/net/unique_fd.hpp"

namespace robogene::net {

class TcpListener {
 public:
  TcpListener() = default;
  // Binds host:port (port 0 = the kernel picks one; read it back with local()). SO_REUSEADDR is
  // set so a restarted server can take its number back at once. Throws NetworkError naming the
  // address and the reason (in use, no such interface...).
  static TcpListener listen(const Endpoint& at, int backlog = 64);

  bool is_open() const noexcept { return fd_.valid(); }
  const Endpoint& local() const noexcept { return local_; }

  // Waits for the next connection; nullopt when interrupted or when `timeout` passes.
  std::optional<TcpStream> accept(Millis timeout = kNoTimeout);
  // Makes a pending or later accept() return nullopt. Safe to call from any thread.
  void interrupt() noexcept;
  void close() noexcept;

 private:
  UniqueFd fd_;
  UniqueFd wake_;  // eventfd written by interrupt()
  Endpoint local_;
};

}  // namespace robogene::net
