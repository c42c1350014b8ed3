// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A TCP connection whose source address is chosen: a peer at 127.0.0.2 looks like another host
// to a port whose allow-list holds only 127.0.0.1 (every 127/8 address reaches the loopback).
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <stdexcept>
#include <string>

#include "robogene/net/tcp_stream.hpp"

namespace robogene::test {

inline net::TcpStream connect_from(const std::string& source, const net::Endpoint& to) {
  net::UniqueFd fd(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
  sockaddr_in from{};
  from.sin_family = AF_INET;
  inet_pton(AF_INET, source.c_str(), &from.sin_addr);
  sockaddr_in dest{};
  dest.sin_family = AF_INET;
  dest.sin_port = htons(static_cast<std::uint16_t>(to.port));
  inet_pton(AF_INET, to.host.c_str(), &dest.sin_addr);
  if (::bind(fd.get(), reinterpret_cast<sockaddr*>(&from), sizeof from) != 0 ||
      ::connect(fd.get(), reinterpret_cast<sockaddr*>(&dest), sizeof dest) != 0) {
    throw std::runtime_error("cannot connect from " + source + " to " + to.to_string());
  }
  return net::TcpStream(std::move(fd));
}

}  // namespace robogene::test
