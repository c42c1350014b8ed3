// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Shared by udp_datagram_fuzz and mcast_datagram_fuzz: what a udp or mcast reader does with
// the datagrams a peer sends after the TCP handshake (carrier_accept_fuzz covers the handshake).
// The input is cut into datagrams; each goes out through a real loopback socket of the carrier
// and is received by the carrier's own reader (DatagramInbound, as the acceptor returns it): the
// 8-byte prefix (CRC, counter), reassembly of a message across datagrams, the index and
// PortCommand, the payload reader, then the Bottle. Datagrams are sent one at a time, when the
// reader asks for the next one, so nothing is lost and an input means the same on every run;
// when the input has no more, the reader is told "nothing arrived in time".
//
// Input: byte 0 = flags (bit 0: the harness computes each CRC; bit 1: the harness numbers the
// datagrams), then records `ctl, len (2 bytes, big-endian), [crc (4)], [counter (4)], len bytes`; the
// crc / counter fields are present only when the flag leaves them to the input. With numbering,
// ctl bit 0 starts a new message (counter 0), else the counter goes on from the last datagram.
//
// Properties: reading ends (no hang) in messages or clean errors; a message never holds more
// than the maximum size, never expects a reply (nobody waits for one on a datagram carrier);
// at most one message per datagram numbered 0; and a data message whose bottle decodes, sent
// again through the carrier's own framer, reads back as the same key and envelope and as the
// bottle its own encoding decodes to (the codec alone already drops the last NUL of a string:
// docs/protocol/bottle.md; the carrier must add nothing to that).
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "robogene/carrier/crc32.hpp"
#include "carrier/datagram_connections.hpp"
#include "robogene/bottle.hpp"
#include "robogene/carrier/message.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"
#include "robogene/net/endpoint.hpp"

namespace robogene::fuzz {

using Datagrams = std::vector<std::vector<std::uint8_t>>;

// The real loopback pair of one carrier: send one datagram, receive one (as UdpSocket::receive).
struct DatagramWire {
  std::function<void(const std::uint8_t*, std::size_t)> send;
  std::function<std::optional<std::size_t>(void*, std::size_t, net::Millis, net::Endpoint*)> receive;
};

// The socket DatagramInbound reads from: each receive sends the next datagram of the input over
// the wire and returns it as the reader socket got it; none left = a timeout.
class WireFeed {
 public:
  WireFeed(const DatagramWire* wire, const Datagrams* datagrams) : wire_(wire), datagrams_(datagrams) {}
  std::optional<std::size_t> receive(void* data, std::size_t capacity, net::Millis, net::Endpoint* from) {
    if (next_ == datagrams_->size()) return std::nullopt;
    const auto& d = (*datagrams_)[next_++];
    wire_->send(d.data(), d.size());
    for (;;) {
      auto n = wire_->receive(data, capacity, net::Millis(5000), from);
      if (!n) __builtin_trap();  // our own loopback datagram was lost
      if (*n == d.size() && std::memcmp(data, d.data(), d.size()) == 0) return n;
      // a datagram of somebody else on the same group and port: not part of this input
    }
  }
  void interrupt() noexcept {}
  void close() noexcept {}

 private:
  const DatagramWire* wire_;
  const Datagrams* datagrams_;
  std::size_t next_ = 0;
};

inline void put_le32(std::vector<std::uint8_t>& out, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}

inline Datagrams datagrams_of_input(const std::uint8_t* data, std::size_t size) {
  Datagrams out;
  if (size == 0) return out;
  const bool fix_crc = data[0] & 1;
  const bool number = data[0] & 2;
  std::size_t at = 1;
  std::int32_t counter = 0;
  auto take = [&](std::size_t n) {
    std::size_t k = std::min(n, size - at);
    const std::uint8_t* p = data + at;
    at += k;
    return std::vector<std::uint8_t>(p, p + k);
  };
  while (at < size) {
    const std::uint8_t ctl = data[at++];
    std::size_t len = 0;
    for (std::uint8_t b : take(2)) len = (len << 8) | b;
    std::vector<std::uint8_t> d(carrier::detail::kDatagramPrefix, 0);
    if (!fix_crc) {
      auto crc = take(4);
      std::copy(crc.begin(), crc.end(), d.begin());
    }
    if (number) {
      counter = (ctl & 1) ? 0 : counter + 1;
      put_le32(d, 4, static_cast<std::uint32_t>(counter));
    } else {
      auto c = take(4);
      std::copy(c.begin(), c.end(), d.begin() + 4);
    }
    auto body = take(len);
    d.insert(d.end(), body.begin(), body.end());
    if (fix_crc) {
      put_le32(d, 0, carrier::crc32(d.data() + carrier::detail::kDatagramPrefix,
                                             d.size() - carrier::detail::kDatagramPrefix));
    }
    out.push_back(std::move(d));
  }
  return out;
}

inline std::vector<std::uint8_t> binary_of(const Bottle& b) { return b.to_bytes(); }

// Sends `b` as `key` through the carrier's framer and reads it back through its reader (whose
// size limit is no concern here: re-encoding may add bytes).
inline void check_round_trip(const DatagramWire& wire, const std::string& carrier, char key,
                             const std::string& envelope, const Bottle& b) {
  constexpr std::size_t max_size = 1u << 20;
  carrier::OutboundMessage out;
  out.key = key;
  out.envelope = envelope;
  out.bottle = &b;
  Datagrams again;
  carrier::detail::DatagramFramer framer;
  framer.send(out, [&](const iovec* parts, std::size_t n) {
    std::vector<std::uint8_t> d;
    for (std::size_t i = 0; i < n; ++i) {
      auto* p = static_cast<const std::uint8_t*>(parts[i].iov_base);
      d.insert(d.end(), p, p + parts[i].iov_len);
    }
    again.push_back(std::move(d));
  });
  carrier::detail::DatagramInbound<WireFeed> reader(WireFeed(&wire, &again), carrier, "/fuzz", "loopback",
                                                   max_size);
  carrier::InboundMessage m;
  if (!reader.read(m)) __builtin_trap();  // our own message did not read back
  if (m.key != key || m.envelope != envelope) __builtin_trap();
  DecodeLimits limits;
  limits.max_bytes = max_size;
  const Bottle expected = Bottle::from_bytes(b.to_bytes(), limits);
  if (binary_of(m.take_bottle(limits)) != binary_of(expected)) __builtin_trap();
  if (reader.read(m)) __builtin_trap();  // one message in, one message out
}

inline int run_datagram_input(const DatagramWire& wire, const std::string& carrier,
                              const std::uint8_t* data, std::size_t size) {
  static const bool quiet = [] {
    log::set_level(log::Level::Error);  // every dropped datagram would log a warning
    return true;
  }();
  (void)quiet;
  // Small enough that inputs reach the "more than the maximum" paths, big enough for blobs.
  constexpr std::size_t kMaxSize = 2048;
  const Datagrams datagrams = datagrams_of_input(data, size);
  std::size_t heads = 0;
  for (const auto& d : datagrams) {
    if (d.size() >= carrier::detail::kDatagramPrefix && carrier::get_int32(d.data() + 4) == 0) ++heads;
  }
  carrier::detail::DatagramInbound<WireFeed> reader(WireFeed(&wire, &datagrams), carrier, "/fuzz", "loopback",
                                                   kMaxSize);
  carrier::InboundMessage m;
  std::size_t messages = 0;
  try {
    while (reader.read(m)) {
      if (++messages > heads) __builtin_trap();
      if (m.reply_expected) __builtin_trap();
      if (m.payload.size() > kMaxSize) __builtin_trap();
      if (m.key != 'd' && m.key != 'D') continue;
      DecodeLimits limits;
      limits.max_bytes = kMaxSize;
      try {
        const Bottle b = m.take_bottle(limits);
        check_round_trip(wire, carrier, m.key, m.envelope, b);
      } catch (const ParseError&) {
        // a malformed bottle is the port's to refuse: the input goes on
      }
    }
  } catch (const Error&) {
    // the reader's own errors are caught inside read(); anything else must still be clean
  }
  return 0;
}

}  // namespace robogene::fuzz
