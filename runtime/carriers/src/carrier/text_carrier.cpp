// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// text (`CONNECT `) and text_ack (`CONNACK `): the sender name is the rest of the first line,
// the acceptor answers "Welcome <name>\r\n".
#include <memory>
#include <string>

#include "robogene/carrier/builtin_carriers.hpp"
#include "robogene/error.hpp"
#include "text_connections.hpp"

namespace robogene::carrier {

namespace {

class TextCarrier final : public Carrier {
 public:
  explicit TextCarrier(bool acks) : acks_(acks) {}
  std::string name() const override { return acks_ ? "text_ack" : "text"; }
  Header header() const override {
    const char* h = acks_ ? "CONNACK " : "CONNECT ";
    Header out;
    for (int i = 0; i < 8; ++i) out[i] = static_cast<std::uint8_t>(h[i]);
    return out;
  }
  bool matches(const Header& h) const override { return h == header(); }
  bool is_text() const override { return true; }

  std::unique_ptr<InboundConnection> accept(std::unique_ptr<Link> link,
                                            const AcceptContext& ctx) const override {
    std::string remote = link->reader.read_line(ctx.max_name_length);
    std::string welcome = "Welcome " + remote + "\r\n";
    link->stream.write_all(welcome.data(), welcome.size());
    return std::make_unique<detail::TextInbound>(std::move(link), name(), acks_, remote,
                                                 ctx.max_message_size, ctx.max_line_length);
  }

  std::unique_ptr<OutboundConnection> connect(std::unique_ptr<Link> link,
                                              const ConnectContext& ctx) const override {
    link->stream.set_read_timeout(ctx.timeout);
    link->stream.set_write_timeout(ctx.timeout);
    Header h = header();
    std::string hello(h.begin(), h.end());
    hello += ctx.sender_name + "\r\n";
    link->stream.write_all(hello.data(), hello.size());
    std::string welcome = link->reader.read_line(4096);
    if (welcome.rfind("Welcome", 0) != 0) {
      throw NetworkError("handshake with " + ctx.target_name + " (" + link->stream.peer_text() +
                         "): expected \"Welcome ...\", got \"" + welcome + "\"");
    }
    return std::make_unique<detail::TextOutbound>(std::move(link), name(), acks_,
                                                  ctx.target_name, 1u << 20, ctx.max_message_size, false);
  }

 private:
  bool acks_;
};

}  // namespace

std::shared_ptr<const Carrier> make_text_carrier(bool with_acks) {
  return std::make_shared<TextCarrier>(with_acks);
}

}  // namespace robogene::carrier
