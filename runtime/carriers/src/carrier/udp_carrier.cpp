// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// udp (reference section 3.6): the handshake runs over tcp like tcp's, but the acceptor answers
// with the number of a fresh UDP port and the tcp socket is dropped. Each message then travels
// as datagrams `int32 crc32(rest), int32 counter, bytes` carrying the same index + PortCommand
// + payload as tcp. No acks, no replies; closing asks the reader to drop its input (as YARP does).
#include <memory>
#include <string>
#include <vector>

#include "binary_framing.hpp"
#include "datagram_connections.hpp"
#include "out_of_band_close.hpp"
#include "robogene/carrier/binary_handshake.hpp"
#include "robogene/carrier/builtin_carriers.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"
#include "robogene/net/udp_socket.hpp"

namespace robogene::carrier {

namespace {

const std::string kUdp = "udp";

class UdpOutbound final : public OutboundConnection {
 public:
  UdpOutbound(net::UdpSocket sock, net::Endpoint to, net::Endpoint reader, std::string remote,
              std::string sender)
      : sock_(std::move(sock)), to_(std::move(to)), reader_(std::move(reader)),
        remote_(std::move(remote)), sender_(std::move(sender)) {}
  const std::string& carrier_name() const override { return kUdp; }
  const std::string& remote_name() const override { return remote_; }
  std::string peer_text() const override { return to_.to_string(); }
  bool is_text() const override { return false; }
  void interrupt() noexcept override { sock_.interrupt(); }
  int socket_fd() const noexcept override { return sock_.fd(); }

  void write_message(const OutboundMessage& m) override {
    framer_.send(m, [&](const iovec* parts, std::size_t n) { sock_.send_to(to_, parts, n); });
  }
  void await_completion(Bottle* reply) override {
    if (reply) reply->clear();  // connectionless: no reply, no ack
  }
  void set_timeout(net::Millis) override {}
  void close() noexcept override {
    if (!sock_.is_open()) return;
    sock_.close();
    detail::close_input_out_of_band(reader_, remote_, sender_);
  }

 private:
  net::UdpSocket sock_;
  net::Endpoint to_;
  net::Endpoint reader_;  // the reader port's tcp address, for the out-of-band close
  std::string remote_;
  std::string sender_;
  detail::DatagramFramer framer_;
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
    std::string remote = read_binary_sender_name(*link, ctx.max_name_length);
    auto sock = net::UdpSocket::bind({link->stream.local().host, 0});
    send_binary_answer(*link, sock.local().port);
    std::string peer = link->stream.peer().host;
    return std::make_unique<detail::DatagramInbound<net::UdpSocket>>(std::move(sock), kUdp, remote, peer,
                                                                    ctx.max_message_size);
  }

  std::unique_ptr<OutboundConnection> connect(std::unique_ptr<Link> link,
                                              const ConnectContext& ctx) const override {
    link->stream.set_read_timeout(ctx.timeout);
    link->stream.set_write_timeout(ctx.timeout);
    send_binary_hello(*link, header(), ctx.sender_name);
    const std::string where = "udp handshake with " + ctx.target_name + " (" + link->stream.peer_text() + ")";
    const std::int32_t port = read_binary_answer(*link, where, "YA <udp port> RP");
    if (port <= 0 || port > 65535) {
      throw NetworkError(where + ": expected YA <udp port> RP, got YA " + std::to_string(port) + " RP");
    }
    net::Endpoint to{link->stream.peer().host, port};
    net::Endpoint reader = link->stream.peer();
    // YARP sends from the port number its tcp socket had; fall back to any if it is taken.
    net::UdpSocket sock;
    try {
      sock = net::UdpSocket::bind(link->stream.local());
    } catch (const NetworkError&) {
      sock = net::UdpSocket::bind({link->stream.local().host, 0});
    }
    link->stream.close();
    return std::make_unique<UdpOutbound>(std::move(sock), to, reader, ctx.target_name, ctx.sender_name);
  }
};

}  // namespace

std::shared_ptr<const Carrier> make_udp_carrier() { return std::make_shared<UdpCarrier>(); }

}  // namespace robogene::carrier
