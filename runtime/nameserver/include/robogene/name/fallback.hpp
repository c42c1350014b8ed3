// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Finding the name server without any configuration, as the paper describes ("sending broadcast
// messages if necessary") and YARP 3 does it (`yarp detect`, FallbackNameServer/Client): the name
// server listens on the multicast group 224.2.1.1 at the default port (10000, or the first number
// of $YARP_PORT_RANGE); a client sends the datagram `NAME_SERVER query /root` there and every
// server answers the group with its text reply ("registration name /root ip ... port ... type
// tcp"). Datagrams carry the udp carrier's 8-byte prefix: int32 crc32(rest), int32 counter (0).
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "robogene/name/name_service.hpp"
#include "robogene/net/endpoint.hpp"
#include "robogene/net/tcp_stream.hpp"

namespace robogene::name {

// 224.2.1.1 at the default port range: 10000, or the first number of $YARP_PORT_RANGE.
net::Endpoint fallback_group();

// Answers `NAME_SERVER ...` datagrams on the group from a thread of its own, joined on the
// interface with address `iface` (the server's --ip). Throws NetworkError naming the group and
// the interface when it cannot join.
class FallbackResponder {
 public:
  FallbackResponder(NameService& service, const std::string& iface, net::Endpoint group = fallback_group());
  ~FallbackResponder();
  FallbackResponder(const FallbackResponder&) = delete;
  FallbackResponder& operator=(const FallbackResponder&) = delete;
  const net::Endpoint& group() const { return group_; }

 private:
  struct Sockets;
  void run();
  NameService& service_;
  net::Endpoint group_;
  std::unique_ptr<Sockets> sockets_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// Asks the group where the name server of `name_space` is, through the interface `iface`
// (three tries within `timeout`); nullopt when no server answered.
std::optional<net::Endpoint> detect_name_server(const std::string& iface, const std::string& name_space = "/root",
                                                net::Millis timeout = net::Millis(1000),
                                                net::Endpoint group = fallback_group());

}  // namespace robogene::name
