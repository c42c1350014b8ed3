// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Attack: many idle connections spread over the ports of one process. Each port bounds its own
// inputs, but a process with many ports had no bound on their sum (a thread each). Now the
// process as a whole serves at most ResourceLimits::max_connections; once the flood leaves,
// everybody is served again.
#include <gtest/gtest.h>

#include "robogene/testing/hostile_util.hpp"
#include "robogene/log.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

TEST(HostileConnections, ProcessServesABoundedNumberOfConnectionsOverAllPorts) {
  log::set_level(log::Level::Error);
  ResourceLimits l = resource_limits();
  l.max_connections = 16;
  ScopedLimits scoped(l);
  Port a, b;
  a.open_at("/a", {"127.0.0.1", 0});
  b.open_at("/b", {"127.0.0.1", 0});
  const ProcessUsage before = ProcessUsage::now();
  std::vector<net::TcpStream> flood;
  for (int i = 0; i < 40; ++i) {
    flood.push_back(connect_to(i % 2 ? a : b));
    try {
      send(flood.back(), hello(carrier::kTcpSpecifier, "/idle" + std::to_string(i)));
    } catch (const std::exception&) {
    }
  }
  std::this_thread::sleep_for(500ms);
  const ProcessUsage during = ProcessUsage::now();
  // 16 serving threads, and the 40 client sockets of this test plus 16 accepted ones.
  EXPECT_LE(during.threads, before.threads + 16 + kDeadlineTimerThread) << "before: " << before.text() << "; during: " << during.text();
  EXPECT_LE(during.fds, before.fds + 40 + 16 + 4) << "before: " << before.text() << "; during: " << during.text();
  flood.clear();
  const ProcessUsage after = usage_when(
      [&](const ProcessUsage& u) { return u.threads <= before.threads + kDeadlineTimerThread; });
  EXPECT_LE(after.threads, before.threads + kDeadlineTimerThread) << after.text();
  EXPECT_TRUE(legit_client_served(a, "/w1"));
  EXPECT_TRUE(legit_client_served(b, "/w2"));
}
