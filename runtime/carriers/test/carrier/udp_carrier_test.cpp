// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// udp carrier (reference section 3.6): tcp handshake answered with a UDP port, then datagrams
// `crc32(rest) LE, counter LE, bytes`, several per large message, bad ones dropped.
#include <gtest/gtest.h>

#include <future>
#include <thread>

#include "robogene/testing/wire_helpers.hpp"
#include "robogene/carrier/registry.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/log.hpp"
#include "robogene/net/udp_socket.hpp"

using namespace robogene;
using namespace robogene::carrier;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

// zlib's crc32, written out independently of the carrier's table-driven one.
std::uint32_t reference_crc32(const std::uint8_t* p, std::size_t n) {
  std::uint32_t c = 0xffffffffu;
  for (std::size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
  }
  return ~c;
}

}  // namespace

TEST(UdpCarrier, InitiatorHandshakesOverTcpThenSendsCrcFramedDatagrams) {
  auto tcp = net::TcpListener::listen({"127.0.0.1", 0});
  auto udp = net::UdpSocket::bind({"127.0.0.1", 0});
  std::vector<std::vector<std::uint8_t>> datagrams;
  std::vector<std::uint8_t> hello;
  std::thread acceptor([&] {
    auto s = tcp.accept(5000ms);
    ASSERT_TRUE(s.has_value());
    hello = read_n(*s, 8 + 4 + 14);
    Header h = make_yarp_number(udp.local().port);
    s->write_all(h.data(), h.size());
    std::vector<std::uint8_t> buf(70000);
    for (int i = 0; i < 5; ++i) {  // one small message, then one of 200000 bytes in 4 datagrams
      auto n = udp.receive(buf.data(), buf.size(), 5000ms);
      ASSERT_TRUE(n.has_value());
      datagrams.emplace_back(buf.begin(), buf.begin() + static_cast<long>(*n));
    }
  });
  ConnectContext ctx;
  ctx.sender_name = "/mc/command:o";
  auto out = open_connection(tcp.local(), "udp", ctx);
  Bottle small = Bottle::from_text("[vmo] 2 7.5");
  std::vector<std::uint8_t> big_body(200000, 0x5a);
  Bottle big{Value::blob(big_body.data(), big_body.size())};
  OutboundMessage m;
  m.bottle = &small;
  out->send(m);
  m.bottle = &big;
  out->send(m);
  acceptor.join();
  EXPECT_EQ(std::vector<std::uint8_t>(hello.begin(), hello.begin() + 8), hex("59 41 61 1e 00 00 52 50"));
  ASSERT_EQ(datagrams.size(), 5u);
  for (std::size_t i = 0; i < datagrams.size(); ++i) {
    const auto& d = datagrams[i];
    ASSERT_GE(d.size(), 8u);
    EXPECT_EQ(static_cast<std::uint32_t>(get_int32(d.data())), reference_crc32(d.data() + 8, d.size() - 8)) << i;
    EXPECT_EQ(get_int32(d.data() + 4), i == 0 ? 0 : static_cast<std::int32_t>(i - 1)) << i;
    EXPECT_LE(d.size(), 65507u);
  }
  // The first datagram carries a whole tcp-style message: index, PortCommand 'D', bottle.
  EXPECT_EQ(std::vector<std::uint8_t>(datagrams[0].begin() + 8, datagrams[0].begin() + 16),
            hex("59 41 0a 00 00 00 52 50"));
  EXPECT_EQ(datagrams[0][8 + 18 + 12 + 5], 'D');
}

TEST(UdpCarrier, AcceptorRepliesItsUdpPortAndDropsCorruptDatagrams) {
  log::set_level(log::Level::Off);
  auto tcp = net::TcpListener::listen({"127.0.0.1", 0});
  std::future<std::unique_ptr<InboundConnection>> accepted = std::async(std::launch::async, [&] {
    auto s = tcp.accept(5000ms);
    return accept_connection(std::move(*s), AcceptContext{});
  });
  auto client = net::TcpStream::connect(tcp.local());
  send(client, hex("59 41 61 1e 00 00 52 50 0e 00 00 00 2f 6d 63 2f 63 6f 6d 6d 61 6e 64 3a 6f 00"));
  auto conn = accepted.get();
  EXPECT_EQ(conn->remote_name(), "/mc/command:o");
  EXPECT_EQ(conn->carrier_name(), "udp");
  auto reply = read_n(client, 8);
  auto port = read_yarp_number(reply.data());
  ASSERT_TRUE(port.has_value());
  auto sock = net::UdpSocket::bind({"127.0.0.1", 0});
  auto message = hex("59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 0c 00 00 00"
                     "00 00 00 00 00 00 00 00 7e 44 00 01 01 01 00 00 01 00 00 00 2a 00 00 00");
  auto datagram = [&](bool corrupt) {
    std::vector<std::uint8_t> d(8);
    put_int32(d.data(), static_cast<std::int32_t>(reference_crc32(message.data(), message.size())));
    put_int32(d.data() + 4, 0);
    d.insert(d.end(), message.begin(), message.end());
    if (corrupt) d.back() ^= 1;
    return d;
  };
  auto bad = datagram(true), good = datagram(false);
  sock.send_to({"127.0.0.1", *port}, bad.data(), bad.size());
  sock.send_to({"127.0.0.1", *port}, good.data(), good.size());
  InboundMessage m;
  ASSERT_TRUE(conn->read(m));
  EXPECT_EQ(m.bottle().to_text(), "42");
  EXPECT_FALSE(m.reply_expected);
  log::set_level(log::Level::Warn);
}

// A message whose last datagram was lost is dropped; the message that follows must not be,
// although its first datagram is what showed the loss (it used to be dropped with it).
TEST(UdpCarrier, TheMessageAfterOneThatLostItsTailIsRead) {
  log::set_level(log::Level::Off);
  auto tcp = net::TcpListener::listen({"127.0.0.1", 0});
  std::future<std::unique_ptr<InboundConnection>> accepted = std::async(std::launch::async, [&] {
    auto s = tcp.accept(5000ms);
    return accept_connection(std::move(*s), AcceptContext{});
  });
  auto client = net::TcpStream::connect(tcp.local());
  send(client, hex("59 41 61 1e 00 00 52 50 03 00 00 00 2f 77 00"));
  auto conn = accepted.get();
  auto port = read_yarp_number(read_n(client, 8).data());
  ASSERT_TRUE(port.has_value());
  auto sock = net::UdpSocket::bind({"127.0.0.1", 0});
  // A one-datagram message carrying the int32 `value`.
  auto message = [](std::uint8_t value) {
    auto m = hex("59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 0c 00 00 00"
                 "00 00 00 00 00 00 00 00 7e 44 00 01 01 01 00 00 01 00 00 00");
    m.insert(m.end(), {value, 0, 0, 0});
    return m;
  };
  auto datagram = [](const std::vector<std::uint8_t>& body, std::int32_t counter) {
    std::vector<std::uint8_t> d(8);
    put_int32(d.data(), static_cast<std::int32_t>(reference_crc32(body.data(), body.size())));
    put_int32(d.data() + 4, counter);
    d.insert(d.end(), body.begin(), body.end());
    return d;
  };
  auto first = message(41);
  auto head = datagram(std::vector<std::uint8_t>(first.begin(), first.begin() + 30), 0);  // its tail is lost
  auto next = datagram(message(42), 0);
  auto last = datagram(message(43), 0);
  for (const auto& d : {head, next, last}) sock.send_to({"127.0.0.1", *port}, d.data(), d.size());
  InboundMessage m;
  ASSERT_TRUE(conn->read(m));
  ASSERT_EQ(m.bottle().to_text(), "42");  // (not 43: else the next read would wait for ever)
  ASSERT_TRUE(conn->read(m));
  EXPECT_EQ(m.bottle().to_text(), "43");
  log::set_level(log::Level::Warn);
}
