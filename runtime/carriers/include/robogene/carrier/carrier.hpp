// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A carrier: how one connection is set up and framed after its 8-byte header. Carriers are
// looked up in a registry by header (acceptor) or by name (initiator); a new carrier plugs in
// by being added to the registry, with no change to the port code.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "robogene/access_policy.hpp"
#include "robogene/bottle.hpp"
#include "robogene/carrier/connection.hpp"
#include "robogene/carrier/mcast_group_allocator.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/limits.hpp"
#include "robogene/net/tcp_stream.hpp"

namespace robogene::carrier {

struct AcceptContext {
  std::string local_name;                          // our port name, for "Welcome" and logs
  std::size_t max_message_size = resource_limits().max_message_size;
  std::size_t max_name_length = 1000;              // YARP's cap on sender names
  std::size_t max_line_length = 1u << 20;          // text carriers
  net::Millis handshake_timeout{10000};            // each read: a silent peer cannot hold a thread
  // The whole handshake, however slowly its bytes drip in (0 = none).
  net::Millis handshake_deadline = resource_limits().handshake_deadline;
  // Who may write through carriers that check it themselves (http refuses writes itself).
  AccessPolicy access;
  // Data messages that change nothing (the name server's query, list...): served to browsers
  // even with HTTP writes off. Unset: every data message counts as a write.
  std::function<bool(const Bottle&)> harmless_data;
  // The 8 bytes that chose the carrier, set by accept_connection: for http they are the start
  // of the request ("GET /dat...").
  Header header{};
};

struct ConnectContext {
  std::string sender_name;      // our port name (or "admin", "anon_rpc"...)
  std::string target_name;      // the port we are connecting to, for logs
  std::size_t max_message_size = 64u * 1024u * 1024u;
  net::Millis timeout{10000};   // handshake and, later, every send
  // Where mcast gets a multicast group (a port passes its name server's); unset = YARP's
  // shared fallback group.
  std::shared_ptr<McastGroupAllocator> mcast_groups;
};

class Carrier {
 public:
  virtual ~Carrier() = default;
  virtual std::string name() const = 0;  // "tcp", "text_ack", ...
  virtual bool matches(const Header& header) const = 0;
  virtual Header header() const = 0;
  virtual bool is_text() const { return false; }
  virtual bool is_connectionless() const { return false; }  // udp, mcast
  // Acceptor side: the 8 header bytes were read already; completes the handshake.
  virtual std::unique_ptr<InboundConnection> accept(std::unique_ptr<Link> link,
                                                    const AcceptContext& ctx) const = 0;
  // Initiator side: `link` is freshly connected; sends the header and does the handshake.
  virtual std::unique_ptr<OutboundConnection> connect(std::unique_ptr<Link> link,
                                                      const ConnectContext& ctx) const = 0;
};

}  // namespace robogene::carrier
