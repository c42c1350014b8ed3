// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Attack: peers that drip a handshake one byte at a time, each byte well inside the per-read
// timeout, so that no single read ever times out. They used to hold a connection and its
// thread for as long as they kept dripping; the deadline for the whole handshake now ends them.
// A legitimate peer that completes its handshake and then sits idle must stay connected.
#include <gtest/gtest.h>

#include <atomic>

#include "robogene/name/local_name_server.hpp"
#include "robogene/testing/hostile_util.hpp"
#include "robogene/log.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

// Sends `bytes` one at a time, `gap` apart, until they run out, the peer hangs up or `stop`.
// Returns whether the peer hung up on us.
bool drip(net::TcpStream& s, const std::vector<std::uint8_t>& bytes, std::chrono::milliseconds gap,
          const std::atomic<bool>& stop) {
  for (std::uint8_t b : bytes) {
    if (stop) return false;
    try {
      s.write_all(&b, 1);
    } catch (const std::exception&) {
      return true;
    }
    std::this_thread::sleep_for(gap);
  }
  // All sent: does the other side hang up?
  s.set_read_timeout(100ms);
  char c;
  try {
    return s.read_some(&c, 1) == 0;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

TEST(HostileDrip, PortEndsHandshakesThatDripPastTheDeadline) {
  log::set_level(log::Level::Error);
  ResourceLimits l = resource_limits();
  l.handshake_deadline = 1000ms;
  ScopedLimits scoped(l);
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});

  // A YARP peer that handshakes and then writes nothing for a while: it must not be cut.
  Port idle_writer;
  idle_writer.open_at("/idle", {"127.0.0.1", 0});
  idle_writer.add_output(Contact{"/r", "tcp", "127.0.0.1", r.contact().port});

  const ProcessUsage before = ProcessUsage::now();
  // A sender name of 200 bytes dripped at 100 ms a byte: 20 s, each read far inside 10 s.
  const auto slow = hello(carrier::kTcpSpecifier, "/" + std::string(199, 'd'));
  std::atomic<bool> stop{false};
  std::atomic<int> cut{0};
  std::vector<std::thread> drippers;
  for (int i = 0; i < 20; ++i) {
    drippers.emplace_back([&] {
      auto s = connect_to(r);
      if (drip(s, slow, 100ms, stop)) ++cut;
    });
  }
  std::this_thread::sleep_for(500ms);
  const ProcessUsage during = ProcessUsage::now();
  // Each dripper stops when the port hangs up on it (after the 1 s deadline) or when its 20 s
  // of bytes run out (the old behaviour: then the count below fails).
  for (auto& t : drippers) t.join();
  EXPECT_EQ(cut.load(), 20) << "the port hung up on every dripping handshake";
  // The drippers were threads of this test process too: compare now that they have finished.
  const ProcessUsage after = ProcessUsage::now();
  EXPECT_LE(after.threads, before.threads + 2) << "during: " << during.text() << "; after: " << after.text();
  EXPECT_LE(after.fds, before.fds + 2) << "before: " << before.text() << "; after: " << after.text();

  std::this_thread::sleep_for(1200ms);  // past the deadline: the idle YARP input stays
  ASSERT_EQ(r.input_names().size(), 1u);
  EXPECT_EQ(r.input_names()[0], "/idle");
  std::thread t([&] { idle_writer.write(Bottle{Value("still here")}); });
  Bottle b;
  EXPECT_TRUE(r.read(b, false, 5000ms));
  t.join();
  EXPECT_EQ(b.to_text(), "\"still here\"");
  EXPECT_TRUE(legit_client_served(r));
}

TEST(HostileDrip, NameServerServesWhileHundredsOfPeersDrip) {
  log::set_level(log::Level::Error);
  name::LocalNameServer ns;
  // 300 connections (over the 256-session limit), each dripping a text command one byte every
  // 200 ms; they never finish a line.
  std::atomic<bool> stop{false};
  std::vector<net::TcpStream> peers;
  for (int i = 0; i < 300; ++i) {
    try {
      peers.push_back(net::TcpStream::connect(ns.contact()));
    } catch (const std::exception&) {
    }
  }
  std::thread dripper([&] {
    const std::string text = "CONNECT /drip\nd\nquery /";
    for (std::size_t k = 0; k < text.size() && !stop; ++k) {
      for (auto& p : peers) {
        try {
          p.write_all(&text[k], 1);
        } catch (const std::exception&) {
        }
      }
      std::this_thread::sleep_for(200ms);
    }
  });
  std::this_thread::sleep_for(600ms);
  bool answered = false;
  try {
    ns.client().register_name("/during-drip", "tcp", "127.0.0.1", 10124);
    answered = ns.client().query("/during-drip").has_value();
  } catch (const std::exception& e) {
    ADD_FAILURE() << e.what();
  }
  stop = true;
  dripper.join();
  EXPECT_TRUE(answered) << "a YARP client's requests must get through while 300 peers drip";
}
