// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// udp (reference section 3.6): the handshake runs over tcp like tcp's, but the acceptor answers
// with the number of a fresh UDP port and the tcp socket is dropped. Each message then travels
// as datagrams `int32 crc32(rest), int32 counter, bytes` carrying the same index + PortCommand
// + payload as tcp. No acks, no replies.
#include <algorithm>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "binary_framing.hpp"
#include "crc32.hpp"
#include "robogene/carrier/builtin_carriers.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"
#include "robogene/net/udp_socket.hpp"
#include "sender_name.hpp"

namespace robogene::carrier {

namespace {

constexpr std::size_t kMaxDatagram = 65507;
constexpr std::size_t kPrefix = 8;
const std::string kUdp = "udp";

class UdpInbound final : public InboundConnection {
 public:
  UdpInbound(net::UdpSocket sock, std::string remote, std::string peer, std::size_t max_size)
      : sock_(std::move(sock)), remote_(std::move(remote)), peer_(std::move(peer)),
        max_size_(max_size), buf_(kMaxDatagram + 64) {}
  const std::string& carrier_name() const override { return kUdp; }
  const std::string& remote_name() const override { return remote_; }
  std::string peer_text() const override { return peer_; }
  bool is_text() const override { return false; }
  void interrupt() noexcept override { sock_.interrupt(); }

  bool read(InboundMessage& m) override {
    for (;;) {
      if (!next_datagram(net::kNoTimeout, true)) return false;
      if (counter_ != 0) continue;  // the tail of a message whose head was lost
      try {
        expected_ = 1;
        std::uint8_t first8[8];
        pull(first8, 8);
        detail::read_message_after_first8(
            first8, [&](void* p, std::size_t n) { pull(p, n); },
            [&](std::size_t n, InboundMessage& mm) {
              mm.detached_blobs.clear();
              mm.detached_blob_ordinals.clear();
              mm.payload.resize(n);
              if (n) pull(mm.payload.data(), n);
            },
            m, max_size_,
            remote_ + " (udp " + peer_ + ")");
        m.reply_expected = false;  // connectionless: nobody waits for a reply
        return true;
      } catch (const Error& e) {
        log::warn(remote_, std::string("dropped a udp message: ") + e.what());
      }
    }
  }
  void reply(const Bottle&) override {}
  void reply_raw(const void*, std::size_t) override {}
  void finish() override {}
  std::unique_ptr<OutboundConnection> reverse() override {
    throw Error("udp connection from " + remote_ + " cannot be reversed (connectionless)");
  }

 private:
  // Receives one datagram and checks its CRC; false when interrupted or timed out.
  bool next_datagram(net::Millis timeout, bool skip_bad) {
    for (;;) {
      net::Endpoint from;
      auto n = sock_.receive(buf_.data(), buf_.size(), timeout, &from);
      if (!n) return false;
      if (*n < kPrefix) {
        if (skip_bad) continue;
        throw ParseError(0, "datagram of " + std::to_string(*n) + " bytes is shorter than its prefix");
      }
      std::uint32_t crc = static_cast<std::uint32_t>(get_int32(buf_.data()));
      if (crc != detail::crc32(buf_.data() + kPrefix, *n - kPrefix)) {
        if (skip_bad) {
          log::warn(remote_, "udp datagram from " + from.to_string() + " failed its CRC check");
          continue;
        }
        throw ParseError(0, "udp datagram from " + from.to_string() + " failed its CRC check");
      }
      counter_ = get_int32(buf_.data() + 4);
      pos_ = kPrefix;
      len_ = *n;
      return true;
    }
  }

  void pull(void* out, std::size_t n) {
    auto* p = static_cast<std::uint8_t*>(out);
    while (n > 0) {
      if (pos_ == len_) {
        if (!next_datagram(net::Millis{2000}, false)) {
          throw NetworkError("udp message from " + remote_ + " stopped arriving mid-message");
        }
        if (counter_ != expected_) {
          throw ParseError(0, "udp datagram " + std::to_string(expected_) + " of a message from " +
                                  remote_ + " was lost (got number " + std::to_string(counter_) + ")");
        }
        ++expected_;
      }
      std::size_t take = std::min(n, len_ - pos_);
      std::memcpy(p, buf_.data() + pos_, take);
      pos_ += take;
      p += take;
      n -= take;
    }
  }

  net::UdpSocket sock_;
  std::string remote_;
  std::string peer_;
  std::size_t max_size_;
  std::vector<std::uint8_t> buf_;
  std::size_t pos_ = 0;
  std::size_t len_ = 0;
  std::int32_t counter_ = 0;
  std::int32_t expected_ = 0;
};

class UdpOutbound final : public OutboundConnection {
 public:
  UdpOutbound(net::UdpSocket sock, net::Endpoint to, std::string remote)
      : sock_(std::move(sock)), to_(std::move(to)), remote_(std::move(remote)) {}
  const std::string& carrier_name() const override { return kUdp; }
  const std::string& remote_name() const override { return remote_; }
  std::string peer_text() const override { return to_.to_string(); }
  bool is_text() const override { return false; }
  void interrupt() noexcept override { sock_.interrupt(); }

  void write_message(const OutboundMessage& m) override {
    if (m.bottle) {
      payload_.encode(*m.bottle);
      detail::frame_message(m, &payload_, head_, iov_);
    } else {
      detail::frame_message(m, nullptr, head_, iov_);
    }
    bytes_.clear();
    for (const iovec& v : iov_) {
      auto* p = static_cast<const std::uint8_t*>(v.iov_base);
      bytes_.insert(bytes_.end(), p, p + v.iov_len);
    }
    payload_.clear();
    std::int32_t counter = 0;
    for (std::size_t at = 0; at < bytes_.size(); at += kMaxDatagram - kPrefix, ++counter) {
      std::size_t n = std::min(kMaxDatagram - kPrefix, bytes_.size() - at);
      std::uint8_t prefix[kPrefix];
      put_int32(prefix, static_cast<std::int32_t>(detail::crc32(bytes_.data() + at, n)));
      put_int32(prefix + 4, counter);
      iovec parts[2] = {{prefix, kPrefix}, {bytes_.data() + at, n}};
      sock_.send_to(to_, parts, 2);
    }
  }
  void await_completion(Bottle* reply) override {
    if (reply) reply->clear();  // connectionless: no reply, no ack
  }
  void set_timeout(net::Millis) override {}
  void close() noexcept override { sock_.close(); }

 private:
  net::UdpSocket sock_;
  net::Endpoint to_;
  std::string remote_;
  EncodedPayload payload_;
  std::vector<std::uint8_t> head_;
  std::vector<iovec> iov_;
  std::vector<std::uint8_t> bytes_;
};

class UdpCarrier final : public Carrier {
 public:
  std::string name() const override { return kUdp; }
  Header header() const override { return make_yarp_number(kUdpSpecifier); }
  bool matches(const Header& h) const override {
    auto n = read_yarp_number(h.data());
    return n && *n >= 7777 && (*n - 7777) % 16 == 0;
  }
  bool is_connectionless() const override { return true; }

  std::unique_ptr<InboundConnection> accept(std::unique_ptr<Link> link,
                                            const AcceptContext& ctx) const override {
    std::string remote = detail::read_binary_sender_name(*link, ctx.max_name_length);
    auto sock = net::UdpSocket::bind({link->stream.local().host, 0});
    Header reply = make_yarp_number(sock.local().port);
    link->stream.write_all(reply.data(), reply.size());
    std::string peer = link->stream.peer().host;
    return std::make_unique<UdpInbound>(std::move(sock), remote, peer, ctx.max_message_size);
  }

  std::unique_ptr<OutboundConnection> connect(std::unique_ptr<Link> link,
                                              const ConnectContext& ctx) const override {
    link->stream.set_read_timeout(ctx.timeout);
    link->stream.set_write_timeout(ctx.timeout);
    std::vector<std::uint8_t> hello;
    Header h = header();
    hello.insert(hello.end(), h.begin(), h.end());
    detail::append_binary_sender_name(hello, ctx.sender_name);
    link->stream.write_all(hello.data(), hello.size());
    std::uint8_t answer[8];
    link->reader.read_exact(answer, 8);
    auto port = read_yarp_number(answer);
    if (!port || *port <= 0 || *port > 65535) {
      throw NetworkError("udp handshake with " + ctx.target_name + " (" +
                         link->stream.peer_text() + "): expected YA <udp port> RP, got " +
                         detail::hex_bytes(answer, 8));
    }
    net::Endpoint to{link->stream.peer().host, *port};
    // YARP sends from the port number its tcp socket had; fall back to any if it is taken.
    net::UdpSocket sock;
    try {
      sock = net::UdpSocket::bind(link->stream.local());
    } catch (const NetworkError&) {
      sock = net::UdpSocket::bind({link->stream.local().host, 0});
    }
    link->stream.close();
    return std::make_unique<UdpOutbound>(std::move(sock), to, ctx.target_name);
  }
};

}  // namespace

std::shared_ptr<const Carrier> make_udp_carrier() { return std::make_shared<UdpCarrier>(); }

}  // namespace robogene::carrier
