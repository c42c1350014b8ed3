// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A bound UDP socket for the datagram carrier: send to an endpoint, receive with a timeout.
#pragma once

#include <cstddef>
#include <optional>

#include "robogene/net/endpoint.hpp"
#include "robogene/net/tcp_stream.hpp"
#include "robogene/net/unique_fd.hpp"

namespace robogene::net {

class UdpSocket {
 public:
  UdpSocket() = default;
  // Binds host:port (0 = ephemeral). Throws NetworkError naming the address.
  static UdpSocket bind(const Endpoint& at);

  bool is_open() const noexcept { return fd_.valid(); }
  int fd() const noexcept { return fd_.get(); }
  const Endpoint& local() const noexcept { return local_; }

  void send_to(const Endpoint& to, const void* data, std::size_t size);
  void send_to(const Endpoint& to, const iovec* iov, std::size_t count);
  // One datagram into `data` (truncated datagrams are an error); nullopt on timeout or after
  // interrupt(). `from` receives the sender.
  std::optional<std::size_t> receive(void* data, std::size_t capacity, Millis timeout,
                                     Endpoint* from = nullptr);
  void interrupt() noexcept;
  void close() noexcept;

 private:
  UniqueFd fd_;
  UniqueFd wake_;
  Endpoint local_;
};

}  // namespace robogene::net
