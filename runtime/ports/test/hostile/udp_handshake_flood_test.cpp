// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Attack: hundreds of udp (and mcast) handshakes whose writers never send a datagram and hang
// up. Each used to leave a thread and a UDP socket (or a group membership) for ever, until the
// port or the name server ran out of connections. Now a port keeps at most
// max_datagram_inputs of them (the longest-silent one makes room) and the name server lets its
// idlest session go when it is full.
#include <gtest/gtest.h>

#include "robogene/name/local_name_server.hpp"
#include "robogene/testing/hostile_util.hpp"
#include "robogene/log.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

// One udp handshake: the acceptor answers with its UDP port; then the attacker leaves.
bool udp_handshake(const net::Endpoint& at, const std::string& sender) {
  try {
    auto s = net::TcpStream::connect(at);
    send(s, hello(carrier::kUdpSpecifier, sender));
    read_n(s, 8);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

TEST(HostileUdpFlood, PortKeepsABoundedNumberOfSilentDatagramInputs) {
  log::set_level(log::Level::Error);
  ResourceLimits l = resource_limits();
  l.max_datagram_inputs = 16;
  ScopedLimits scoped(l);
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  const ProcessUsage before = ProcessUsage::now();

  int answered = 0;
  for (int i = 0; i < 300; ++i) answered += udp_handshake({"127.0.0.1", r.contact().port}, "/udp" + std::to_string(i));
  EXPECT_EQ(answered, 300) << "every handshake is answered; the old inputs make room";

  // 16 inputs may stay (a thread each, and a UDP socket with its wake-up eventfd), plus a few
  // connections winding down.
  const std::size_t slack = 8;
  ProcessUsage after = usage_when([&](const ProcessUsage& u) {
    return u.threads <= before.threads + 16 + slack && u.fds <= before.fds + 2 * 16 + slack;
  });
  EXPECT_LE(after.threads, before.threads + 16 + slack) << "before: " << before.text() << "; after: " << after.text();
  EXPECT_LE(after.fds, before.fds + 2 * 16 + slack) << "before: " << before.text() << "; after: " << after.text();
  EXPECT_TRUE(legit_client_served(r));
}

TEST(HostileUdpFlood, NameServerStillAnswersAfterUdpHandshakes) {
  log::set_level(log::Level::Error);
  name::LocalNameServer ns;
  const ProcessUsage before = ProcessUsage::now();
  for (int i = 0; i < 300; ++i) udp_handshake(ns.contact(), "/udp" + std::to_string(i));
  // Default name server limit: 256 sessions. A YARP client's request must get through.
  ns.client().register_name("/after-flood", "tcp", "127.0.0.1", 10123);
  auto c = ns.client().query("/after-flood");
  ASSERT_TRUE(c.has_value()) << "the name server no longer answers after 300 udp handshakes";
  EXPECT_EQ(c->port, 10123);
  const ProcessUsage after = ProcessUsage::now();
  EXPECT_LE(after.threads, before.threads + 256 + 64 + 8) << after.text();
}

TEST(HostileUdpFlood, McastHandshakesNamingManyGroupsAreBounded) {
  log::set_level(log::Level::Error);
  ResourceLimits l = resource_limits();
  l.max_datagram_inputs = 8;
  ScopedLimits scoped(l);
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  const ProcessUsage before = ProcessUsage::now();
  int joined = 0;
  for (int i = 0; i < 60; ++i) {
    try {
      auto s = connect_to(r);
      auto b = hello(carrier::kMcastSpecifier, "/mc" + std::to_string(i));
      // A different group each time: 239.255.<i>.<i>, port 20000 + i.
      const int port = 20000 + i;
      std::vector<std::uint8_t> group = {239, 255, static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(i + 1),
                                         static_cast<std::uint8_t>(port / 256), static_cast<std::uint8_t>(port % 256)};
      b.insert(b.end(), group.begin(), group.end());
      send(s, b);
      // The acceptor hangs up once it has joined.
      char c;
      s.set_read_timeout(5000ms);
      if (s.read_some(&c, 1) == 0) ++joined;
    } catch (const std::exception&) {
    }
  }
  if (joined == 0) GTEST_SKIP() << "no multicast on this host's loopback";
  const std::size_t slack = 6;
  ProcessUsage after = usage_when([&](const ProcessUsage& u) {
    return u.threads <= before.threads + 8 + slack && u.fds <= before.fds + 2 * 8 + slack;
  });
  EXPECT_LE(after.threads, before.threads + 8 + slack) << "before: " << before.text() << "; after: " << after.text();
  EXPECT_LE(after.fds, before.fds + 2 * 8 + slack) << "before: " << before.text() << "; after: " << after.text();
  EXPECT_TRUE(legit_client_served(r));
}
