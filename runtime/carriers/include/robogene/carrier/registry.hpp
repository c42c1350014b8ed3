// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The carriers this process speaks. The built-in ones (tcp, fast_tcp, text, text_ack, udp, mcast,
// shmem, http) are present from the start; others (name_ser...) are added with add().
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "robogene/carrier/carrier.hpp"
#include "robogene/net/endpoint.hpp"

namespace robogene::carrier {

class CarrierRegistry {
 public:
  static CarrierRegistry& global();

  // Adds `c`, replacing any carrier of the same name.
  void add(std::shared_ptr<const Carrier> c);
  std::shared_ptr<const Carrier> find(std::string_view name) const;
  std::shared_ptr<const Carrier> find(const Header& header) const;
  std::vector<std::string> names() const;

 private:
  CarrierRegistry();
  mutable std::mutex mutex_;
  std::vector<std::shared_ptr<const Carrier>> carriers_;
};

// What YARP tells a peer whose first 8 bytes match no carrier (then it closes the socket).
std::string protocol_not_found_text(const Header& header);

// Acceptor entry point: reads the 8-byte header (within ctx.handshake_timeout), picks the
// carrier, completes the handshake. On an unknown header, writes protocol_not_found_text, closes
// and throws NetworkError naming the peer and the bytes.
std::unique_ptr<InboundConnection> accept_connection(net::TcpStream stream,
                                                     const AcceptContext& ctx,
                                                     const CarrierRegistry& registry =
                                                         CarrierRegistry::global());

// Initiator entry point: connects to `at` and handshakes with the named carrier. Throws
// NetworkError naming the address, or robogene::Error for an unknown carrier name.
std::unique_ptr<OutboundConnection> open_connection(const net::Endpoint& at,
                                                    std::string_view carrier_name,
                                                    const ConnectContext& ctx,
                                                    const CarrierRegistry& registry =
                                                        CarrierRegistry::global());

}  // namespace robogene::carrier
