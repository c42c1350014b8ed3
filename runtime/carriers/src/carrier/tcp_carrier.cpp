// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// tcp and fast_tcp: binary handshake (header, sender name, `YA <port> RP`), then indexed messages.
#include <memory>
#include <string>
#include <vector>

#include "binary_connections.hpp"
#include "binary_framing.hpp"
#include "robogene/carrier/binary_handshake.hpp"
#include "robogene/carrier/builtin_carriers.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/error.hpp"

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
    std::string remote = read_binary_sender_name(*link, ctx.max_name_length);
    send_binary_answer(*link, link->stream.local().port);
    return std::make_unique<detail::BinaryInbound>(std::move(link), name(), acks_, remote,
                                                   ctx.max_message_size, ctx.handshake_timeout);
  }

  std::unique_ptr<OutboundConnection> connect(std::unique_ptr<Link> link,
                                              const ConnectContext& ctx) const override {
    link->stream.set_read_timeout(ctx.timeout);
    link->stream.set_write_timeout(ctx.timeout);
    send_binary_hello(*link, header(), ctx.sender_name);
    read_binary_answer(*link, "handshake with " + ctx.target_name + " (" + link->stream.peer_text() + ")",
                       "YA <port> RP after the " + name() + " header");
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
