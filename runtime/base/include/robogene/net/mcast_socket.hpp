// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// IPv4 multicast sockets, for the mcast carrier and the name server's multicast fallback. A
// reader binds the group's address and port with SO_REUSEADDR, so that every reader on one host
// gets its own copy of each datagram, and joins the group on one interface; a sender sends
// through one interface with loopback on, so readers on the sender's own host hear it too (also
// over 127.0.0.1).
#pragma once

#include <sys/uio.h>

#include <cstddef>
#include <optional>
#include <string>

#include "robogene/net/endpoint.hpp"
#include "robogene/net/tcp_stream.hpp"
#include "robogene/net/unique_fd.hpp"

namespace robogene::net {

// True for 224.0.0.0 .. 239.255.255.255.
bool is_multicast_group(const std::string& dotted_quad);

class McastSocket {
 public:
  McastSocket() = default;
  // Reader: bound to group.host:group.port and joined on the interface with address `iface`.
  // Throws NetworkError naming the group and the interface.
  static McastSocket join(const Endpoint& group, const std::string& iface);
  // Sender through the interface with address `iface` (time-to-live 1: the local network).
  static McastSocket sender(const std::string& iface);

  void send_to(const Endpoint& to, const iovec* iov, std::size_t count);
  // As UdpSocket::receive: nullopt on timeout or after interrupt().
  std::optional<std::size_t> receive(void* data, std::size_t capacity, Millis timeout,
                                     Endpoint* from = nullptr);
  void interrupt() noexcept;
  void close() noexcept;

 private:
  UniqueFd fd_;
  UniqueFd wake_;
  std::string where_;  // "group 224.1.1.3:10005 on 127.0.0.1", for errors
};

}  // namespace robogene::net
