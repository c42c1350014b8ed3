// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// tcp and fast_tcp: binary handshake (header, sender name, `YA <port> RP`), then indexed messages.
#include <memory>
#include <string>
#include <vector>

#include "binary_connections.hpp"
#include "binary_framing.hpp"
#include "robogene/carrier/builtin_carriers.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/error.hpp"
#include "sender_name.hpp"

namespace robogene::carrier {

namespace {

class TcpCarrier final : public Carrier {
 public:
  explicit TcpCarrier(bool acks) : acks_(acks) {}
  std::string name() const override { return acks_ ? "tcp" : "fast_tcp"; }
  Header header() const override {
    return make_yarp_number(acks_ ? kTcpSpecifier : kFastTcpSpecifier);
  }
  bool matches(const Header& h) const override {
    auto n = read_yarp_number(h.data());
    if (!n || *n < 7777) return false;
    int spec = *n - 7777;
    return spec % 16 == 3 && ((spec & 128) != 0) == acks_;
  }

  std::unique_ptr<InboundConnection> accept(std::unique_ptr<Link> link,
                                            const AcceptContext& ctx) const override {
    std::string remote = detail::read_binary_sender_name(*link, ctx.max_name_length);
    Header reply = make_yarp_number(link->stream.local().port);
    link->stream.write_all(reply.data(), reply.size());
    return std::make_unique<detail::BinaryInbound>(std::move(link), name(), acks_, remote,
                                                   ctx.max_message_size, ctx.handshake_timeout);
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
    if (!read_yarp_number(answer)) {
      throw NetworkError("handshake with " + ctx.target_name + " (" + link->stream.peer_text() +
                         "): expected YA <port> RP after the " + name() + " header, got " +
                         detail::hex_bytes(answer, 8));
    }
    return std::make_unique<detail::BinaryOutbound>(std::move(link), name(), acks_,
                                                    ctx.target_name, ctx.max_message_size);
  }

 private:
  bool acks_;
};

}  // namespace

std::shared_ptr<const Carrier> make_tcp_carrier(bool with_acks) {
  return std::make_shared<TcpCarrier>(with_acks);
}

}  // namespace robogene::carrier
