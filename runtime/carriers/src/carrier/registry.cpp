// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/carrier/registry.hpp"

#include <cstdio>

#include "binary_framing.hpp"
#include "handshake_deadline.hpp"
#include "robogene/carrier/builtin_carriers.hpp"
#include "robogene/error.hpp"

namespace robogene::carrier {

CarrierRegistry::CarrierRegistry() {
  carriers_.push_back(make_tcp_carrier(true));
  carriers_.push_back(make_tcp_carrier(false));
  carriers_.push_back(make_text_carrier(false));
  carriers_.push_back(make_text_carrier(true));
  carriers_.push_back(make_udp_carrier());
  carriers_.push_back(make_mcast_carrier());
  carriers_.push_back(make_shmem_carrier());
  carriers_.push_back(make_http_carrier());
}

CarrierRegistry& CarrierRegistry::global() {
  static CarrierRegistry registry;
  return registry;
}

void CarrierRegistry::add(std::shared_ptr<const Carrier> c) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto& existing : carriers_) {
    if (existing->name() == c->name()) {
      existing = std::move(c);
      return;
    }
  }
  carriers_.push_back(std::move(c));
}

std::shared_ptr<const Carrier> CarrierRegistry::find(std::string_view name) const {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& c : carriers_) {
    if (c->name() == name) return c;
  }
  return nullptr;
}

std::shared_ptr<const Carrier> CarrierRegistry::find(const Header& header) const {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& c : carriers_) {
    if (c->matches(header)) return c;
  }
  return nullptr;
}

std::vector<std::string> CarrierRegistry::names() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> out;
  for (const auto& c : carriers_) out.push_back(c->name());
  return out;
}

std::string protocol_not_found_text(const Header& header) {
  std::string hex;
  for (std::uint8_t b : header) {
    char buf[8];
    std::snprintf(buf, sizeof buf, " %d", static_cast<int>(b));
    hex += buf;
  }
  return "* Error. Protocol not found.\r\n"
         "* Hello. You appear to be trying to communicate with a YARP Port.\r\n"
         "* The first 8 bytes sent to a YARP Port are critical for identifying the\r\n"
         "* protocol you wish to speak.\r\n"
         "* The first 8 bytes you sent were:" + hex + "\r\n"
         "* This is not a protocol this port knows.\r\n"
         "* If you are a human, try typing \"CONNECT foo\" and pressing return.\r\n"
         "* Then type \"?\" for help.\r\n";
}

std::unique_ptr<InboundConnection> accept_connection(net::TcpStream stream,
                                                     const AcceptContext& ctx,
                                                     const CarrierRegistry& registry) {
  auto link = std::make_unique<Link>(std::move(stream));
  link->stream.set_read_timeout(ctx.handshake_timeout);
  link->stream.set_write_timeout(ctx.handshake_timeout);
  const std::string peer = link->stream.peer_text();
  detail::HandshakeDeadline deadline(link->stream.fd(), ctx.handshake_deadline);
  auto late = [&] {
    return NetworkError("connection from " + peer + ": handshake not complete within " +
                        std::to_string(ctx.handshake_deadline.count()) +
                        " ms (the deadline for the whole handshake; ROBOGENE_HANDSHAKE_DEADLINE_MS)");
  };
  Header header;
  try {
    link->reader.read_exact(header.data(), header.size());
  } catch (const Error&) {
    if (deadline.expired()) throw late();
    throw;
  }
  auto carrier = registry.find(header);
  if (!carrier) {
    std::string text = protocol_not_found_text(header);
    try {
      link->stream.write_all(text.data(), text.size());
    } catch (const NetworkError&) {
      // The peer may not be listening; the error below is what matters.
    }
    link->stream.shutdown();
    throw NetworkError("connection from " + peer + ": unknown carrier header " +
                       detail::hex_bytes(header.data(), header.size()));
  }
  AcceptContext with_header = ctx;
  with_header.header = header;
  std::unique_ptr<InboundConnection> in;
  try {
    in = carrier->accept(std::move(link), with_header);
  } catch (const Error&) {
    if (deadline.expired()) throw late();
    throw;
  }
  if (deadline.expired()) throw late();
  return in;
}

std::unique_ptr<OutboundConnection> open_connection(const net::Endpoint& at,
                                                    std::string_view carrier_name,
                                                    const ConnectContext& ctx,
                                                    const CarrierRegistry& registry) {
  auto carrier = registry.find(carrier_name);
  if (!carrier) {
    throw Error("unknown carrier \"" + std::string(carrier_name) + "\" for a connection to " +
                ctx.target_name + " at " + at.to_string());
  }
  auto link = std::make_unique<Link>(net::TcpStream::connect(at, ctx.timeout));
  return carrier->connect(std::move(link), ctx);
}

}  // namespace robogene::carrier
