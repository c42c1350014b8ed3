// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// mcast (reference section 3.6; YARP's McastCarrier): the writer connects to each reader over
// tcp and sends `YA 62 1e 00 00 RP`, its name, and 6 bytes naming the multicast group (4 IPv4
// octets, port big-endian). Nobody answers: the reader joins the group and hangs up, and from
// then on every message travels as udp-style datagrams to the group, once for all readers.
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "binary_framing.hpp"
#include "datagram_connections.hpp"
#include "mcast_group.hpp"
#include "robogene/net/mcast_socket.hpp"
#include "out_of_band_close.hpp"
#include "robogene/carrier/binary_handshake.hpp"
#include "robogene/carrier/builtin_carriers.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"

namespace robogene::carrier {

namespace {

const std::string kMcast = "mcast";

// The 6 header bytes after the sender name: 224 1 1 3, then the port as 256 * b4 + b5.
std::vector<std::uint8_t> group_bytes(const net::Endpoint& group) {
  std::vector<std::uint8_t> out;
  unsigned a[4] = {0, 0, 0, 0};
  if (std::sscanf(group.host.c_str(), "%u.%u.%u.%u", &a[0], &a[1], &a[2], &a[3]) != 4) {
    throw NetworkError("mcast group " + group.host + " is not a dotted quad");
  }
  for (unsigned v : a) out.push_back(static_cast<std::uint8_t>(v));
  out.push_back(static_cast<std::uint8_t>(group.port / 256));
  out.push_back(static_cast<std::uint8_t>(group.port % 256));
  return out;
}

net::Endpoint parse_group_bytes(const std::uint8_t* b) {
  net::Endpoint e;
  e.host = std::to_string(b[0]) + "." + std::to_string(b[1]) + "." + std::to_string(b[2]) + "." +
           std::to_string(b[3]);
  e.port = 256 * b[4] + b[5];
  return e;
}

class McastOutbound final : public OutboundConnection {
 public:
  McastOutbound(std::string key, net::Endpoint reader, std::string target, std::string sender)
      : key_(std::move(key)), reader_(std::move(reader)), target_(std::move(target)),
        sender_(std::move(sender)) {}
  ~McastOutbound() override { detail::McastGroups::global().leave(key_, this); }

  void attach(std::shared_ptr<detail::McastGroup> g) { group_ = std::move(g); }
  const std::string& carrier_name() const override { return kMcast; }
  const std::string& remote_name() const override { return target_; }
  std::string peer_text() const override { return reader_.to_string() + " via " + group_->address.to_string(); }
  bool is_text() const override { return false; }
  void interrupt() noexcept override {}

  void write_message(const OutboundMessage& m) override {
    std::lock_guard<std::mutex> lock(group_->mutex);
    if (group_->members.empty() || group_->members.front() != this) return;  // the elect sends for all
    framer_.send(m, [&](const iovec* parts, std::size_t n) { group_->socket.send_to(group_->address, parts, n); });
  }
  void await_completion(Bottle* reply) override {
    if (reply) reply->clear();  // connectionless: no reply, no ack
  }
  void set_timeout(net::Millis) override {}
  void close() noexcept override {
    if (closed_) return;
    closed_ = true;
    detail::McastGroups::global().leave(key_, this);
    detail::close_input_out_of_band(reader_, target_, sender_);
  }

 private:
  std::string key_;
  net::Endpoint reader_;
  std::string target_;
  std::string sender_;
  std::shared_ptr<detail::McastGroup> group_;
  detail::DatagramFramer framer_;
  bool closed_ = false;
};

class McastCarrier final : public Carrier {
 public:
  std::string name() const override { return kMcast; }
  Header header() const override { return make_yarp_number(kMcastSpecifier); }
  bool matches(const Header& h) const override {
    auto n = read_yarp_number(h.data());
    return n && *n >= 7777 && (*n - 7777) % 16 == 1;
  }
  bool is_connectionless() const override { return true; }

  std::unique_ptr<InboundConnection> accept(std::unique_ptr<Link> link,
                                            const AcceptContext& ctx) const override {
    std::string remote = read_binary_sender_name(*link, ctx.max_name_length);
    std::uint8_t b[6];
    link->reader.read_exact(b, 6);
    net::Endpoint group = parse_group_bytes(b);
    std::string peer = link->stream.peer_text();
    if (!net::is_multicast_group(group.host) || group.port == 0) {
      throw NetworkError("mcast connection from " + remote + " (" + peer + "): " + group.to_string() +
                         " is not a multicast group and port");
    }
    auto sock = net::McastSocket::join(group, link->stream.local().host);
    link->stream.close();  // joined: the writer waits for this hang-up before it sends
    log::debug(ctx.local_name, "joined mcast group " + group.to_string() + " for " + remote);
    return std::make_unique<detail::DatagramInbound<net::McastSocket>>(
        std::move(sock), kMcast, remote, peer + " via " + group.to_string(), ctx.max_message_size);
  }

  std::unique_ptr<OutboundConnection> connect(std::unique_ptr<Link> link,
                                              const ConnectContext& ctx) const override {
    const std::string iface = link->stream.local().host;
    const std::string key = ctx.sender_name + "/net=" + iface;
    auto out = std::make_unique<McastOutbound>(key, link->stream.peer(), ctx.target_name, ctx.sender_name);
    auto group = detail::McastGroups::global().enlist(key, out.get(), ctx.sender_name, iface,
                                                      ctx.mcast_groups, ctx.timeout);
    out->attach(group);
    link->stream.set_write_timeout(ctx.timeout);
    send_binary_hello(*link, header(), ctx.sender_name, group_bytes(group->address));
    await_hang_up(*link, ctx);
    return out;
  }

 private:
  // The reader sends nothing and closes once it has joined the group; waiting for that keeps a
  // write made right after connecting from going out before anyone listens. Bytes instead of
  // the hang-up mean the peer does not speak mcast (e.g. YARP's "Protocol not found" text).
  static void await_hang_up(Link& link, const ConnectContext& ctx) {
    link.stream.set_read_timeout(std::min(ctx.timeout, net::Millis{2000}));
    char buf[512];
    std::size_t n = 0;
    try {
      n = link.stream.read_some(buf, sizeof buf);
    } catch (const NetworkError& e) {
      log::debug(ctx.sender_name, "mcast reader " + ctx.target_name + " kept its handshake socket open: " + e.what());
      return;
    }
    if (n > 0) {
      std::string said(buf, n);
      throw NetworkError("mcast handshake with " + ctx.target_name + " (" + link.stream.peer_text() +
                         "): the peer answered instead of joining the group: \"" +
                         said.substr(0, said.find('\n')) + "\"");
    }
  }
};

}  // namespace

std::shared_ptr<const Carrier> make_mcast_carrier() { return std::make_shared<McastCarrier>(); }

}  // namespace robogene::carrier
