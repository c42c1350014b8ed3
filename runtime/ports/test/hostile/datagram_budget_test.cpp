// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Attack on memory through a datagram carrier: a udp writer's big message used to be gathered
// outside the process's bytes-in-transit budget (every udp input of every port could hold one
// message of up to the message size while its datagrams arrived). Now a big udp message counts
// in the budget as tcp's does: one that would pass it is dropped, and the next one is read.
#include <gtest/gtest.h>

#include <future>

#include "robogene/testing/hostile_util.hpp"
#include "robogene/carrier/registry.hpp"
#include "robogene/log.hpp"
#include "robogene/net/tcp_listener.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

TEST(HostileDatagram, BigUdpMessagesCountInTheProcessBudget) {
  log::set_level(log::Level::Error);
  ResourceLimits l = resource_limits();
  l.max_receiving_bytes = 128u << 10;
  ScopedLimits scoped(l);
  auto tcp = net::TcpListener::listen({"127.0.0.1", 0});
  auto accepted = std::async(std::launch::async, [&] {
    auto s = tcp.accept(5000ms);
    return carrier::accept_connection(std::move(*s), carrier::AcceptContext{});
  });
  carrier::ConnectContext ctx;
  ctx.sender_name = "/w";
  ctx.target_name = "/r";
  auto out = carrier::open_connection(tcp.local(), "udp", ctx);
  auto in = accepted.get();
  // The reader reads while the datagrams come (a loopback socket buffer holds few of them).
  auto first = std::async(std::launch::async, [&] {
    carrier::InboundMessage m;
    return in->read(m) ? m.bottle().to_text().substr(0, 20) : std::string("(nothing)");
  });
  const Bottle big{Value::blob(std::vector<std::uint8_t>(300u << 10, 1))};
  const Bottle small{Value("after")};
  carrier::OutboundMessage m;
  m.bottle = &big;
  out->write_message(m);
  std::this_thread::sleep_for(200ms);
  m.bottle = &small;
  out->write_message(m);
  EXPECT_EQ(first.get(), "after") << "the 300 KB message passes the 128 KB budget and is dropped";
  EXPECT_EQ(ResourceUsage::global().receiving_bytes(), 0u);
  in->interrupt();
}
