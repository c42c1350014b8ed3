// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Attack: one remote address (127.0.0.2) floods a process with connections, idle after a valid
// handshake or never finishing it. The process-wide limit kept the process alive, but the flood
// took every slot, so a peer at another address (127.0.0.1) was refused until the flood left.
// Now each address gets at most max_connections_per_address of them, and at most
// max_handshakes_per_address still in their handshake: the other address is served meanwhile.
#include <gtest/gtest.h>

#include "robogene/testing/connect_from.hpp"
#include "robogene/testing/hostile_util.hpp"
#include "robogene/log.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

ResourceLimits small_limits() {
  ResourceLimits l = resource_limits();
  l.max_connections = 24;
  l.max_connections_per_address = 8;
  l.max_handshakes_per_address = 4;
  return l;
}

// True when the port hung up on `s` (refused it) within a second.
bool hung_up(net::TcpStream& s) {
  s.set_read_timeout(1000ms);
  char c;
  try {
    return s.read_some(&c, 1) == 0;
  } catch (const NetworkError&) {
    return false;  // still open: the read timed out
  }
}

}  // namespace

TEST(HostilePeerAddress, AnAddressFloodingWithIdleConnectionsLeavesRoomForAnother) {
  log::set_level(log::Level::Error);
  ScopedLimits scoped(small_limits());
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  const ProcessUsage before = ProcessUsage::now();
  // One after the other, each handshake finished (the port's answer read) before the next.
  std::vector<net::TcpStream> flood;
  int refused = 0;
  for (int i = 0; i < 40; ++i) {
    flood.push_back(connect_from("127.0.0.2", r.contact().endpoint()));
    try {
      send(flood.back(), hello(carrier::kTcpSpecifier, "/idle" + std::to_string(i)));
      read_n(flood.back(), 8);
    } catch (const std::exception&) {
      ++refused;  // closed by the port
    }
  }
  const ProcessUsage during = ProcessUsage::now();
  EXPECT_EQ(refused, 32) << "every connection from 127.0.0.2 past its 8 is refused";
  EXPECT_EQ(ResourceUsage::global().connections_from("127.0.0.2"), 8u);
  EXPECT_LE(during.threads, before.threads + 8 + kDeadlineTimerThread) << "before: " << before.text() << "; during: " << during.text();
  EXPECT_TRUE(legit_client_served(r, "/w1")) << "127.0.0.1 is served while 127.0.0.2 floods";
  flood.clear();
  usage_when([&](const ProcessUsage&) { return ResourceUsage::global().connections_from("127.0.0.2") == 0; });
  EXPECT_EQ(ResourceUsage::global().connections_from("127.0.0.2"), 0u);
  // Once the flood has left, the address gets its connections back.
  auto again = connect_from("127.0.0.2", r.contact().endpoint());
  send(again, hello(carrier::kTcpSpecifier, "/again"));
  EXPECT_FALSE(hung_up(again));
}

TEST(HostilePeerAddress, AnAddressHoldingHandshakesOpenLeavesRoomForAnother) {
  log::set_level(log::Level::Error);
  ScopedLimits scoped(small_limits());
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  const ProcessUsage before = ProcessUsage::now();
  // Connections that send half a header and stop: each holds its handshake until the deadline.
  std::vector<net::TcpStream> stalled;
  for (int i = 0; i < 40; ++i) {
    stalled.push_back(connect_from("127.0.0.2", r.contact().endpoint()));
    try {
      send(stalled.back(), std::string("YA"));
    } catch (const std::exception&) {
    }
  }
  std::this_thread::sleep_for(500ms);
  const ProcessUsage during = ProcessUsage::now();
  EXPECT_EQ(ResourceUsage::global().handshakes_from("127.0.0.2"), 4u);
  EXPECT_LE(during.threads, before.threads + 4 + kDeadlineTimerThread) << "before: " << before.text() << "; during: " << during.text();
  EXPECT_TRUE(legit_client_served(r, "/w1")) << "127.0.0.1 is served while 127.0.0.2 stalls handshakes";
  // A handshake that completes stops counting as one in flight.
  EXPECT_EQ(ResourceUsage::global().handshakes_from("127.0.0.1"), 0u);
  stalled.clear();
  usage_when([&](const ProcessUsage&) { return ResourceUsage::global().connections_from("127.0.0.2") == 0; });
  EXPECT_EQ(ResourceUsage::global().handshakes_from("127.0.0.2"), 0u);
}
