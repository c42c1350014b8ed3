// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Bad peers: garbage, truncation, oversized messages, vanishing peers, stalled readers,
// anonymous senders and a rooted sender reconnecting. The port must log a line naming the peer
// and what was wrong, drop the one connection and keep serving everybody else.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <initializer_list>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "robogene/testing/wire_helpers.hpp"
#include "robogene/testing/port_test_util.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

const char kHelloW[] = "59 41 e4 1e 00 00 52 50 03 00 00 00 2f 77 00";

// Waits until `pred` holds (or 5 s pass).
template <typename Pred>
bool eventually(Pred pred) {
  for (int i = 0; i < 500; ++i) {
    if (pred()) return true;
    std::this_thread::sleep_for(10ms);
  }
  return pred();
}

// The port still works: a fresh writer gets a message through.
void expect_still_serving(Port& r) {
  Port w;
  w.open_at("/probe", {"127.0.0.1", 0});
  w.add_output(Contact{r.name(), "tcp", "127.0.0.1", r.contact().port});
  std::thread t([&] { w.write(Bottle{Value("alive")}); });
  Bottle b;
  EXPECT_TRUE(r.read(b, false, 5000ms));
  t.join();
  EXPECT_EQ(b.to_text(), "alive");
}

bool closed_by_peer(net::TcpStream& s) {
  s.set_read_timeout(5000ms);
  char c;
  try {
    return s.read_some(&c, 1) == 0;
  } catch (const NetworkError&) {
    return true;
  }
}

}  // namespace

// Captures what the ports log, so each test can check the line that names what went wrong.
class PortRobustness : public ::testing::Test {
 protected:
  void SetUp() override {
    log::set_level(log::Level::Warn);
    log::set_sink([this](log::Level, std::string_view who, std::string_view text) {
      std::lock_guard<std::mutex> lock(mutex_);
      lines_.push_back(std::string(who) + ": " + std::string(text));
    });
  }
  void TearDown() override { log::set_sink({}); }

  // Waits (up to 5 s) for a logged line holding every fragment; on failure, shows what was logged.
  ::testing::AssertionResult logged(std::initializer_list<std::string> fragments) {
    auto found = [&] {
      std::lock_guard<std::mutex> lock(mutex_);
      for (const auto& line : lines_) {
        bool all = true;
        for (const auto& f : fragments) all = all && line.find(f) != std::string::npos;
        if (all) return true;
      }
      return false;
    };
    if (eventually(found)) return ::testing::AssertionSuccess();
    std::lock_guard<std::mutex> lock(mutex_);
    std::string seen;
    for (const auto& line : lines_) seen += "\n  " + line;
    return ::testing::AssertionFailure() << "no such line; logged:" << seen;
  }

 private:
  std::mutex mutex_;
  std::vector<std::string> lines_;
};

TEST_F(PortRobustness, GarbageIndexClosesThatConnectionOnly) {
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  auto s = net::TcpStream::connect({"127.0.0.1", r.contact().port});
  send(s, hex(kHelloW));
  read_n(s, 8);
  send(s, std::string("this is not an index at all"));
  EXPECT_TRUE(closed_by_peer(s));
  expect_still_serving(r);
  EXPECT_TRUE(logged({"/r: input from /w (127.0.0.1:", "expected index header YA 0a 00 00 00 RP at byte offset 0"}));
}

TEST_F(PortRobustness, BadPortCommandMarkerIsRejected) {
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  auto s = net::TcpStream::connect({"127.0.0.1", r.contact().port});
  send(s, hex(kHelloW));
  read_n(s, 8);
  send(s, hex("59 41 0a 00 00 00 52 50 01 01 ff ff ff ff ff ff ff ff 08 00 00 00 00 00 00 00"
              "00 00 00 00 21 44 00 01"));
  EXPECT_TRUE(closed_by_peer(s));
  expect_still_serving(r);
  EXPECT_TRUE(logged({"/r: input from /w (127.0.0.1:", "expected '~' (0x7e) at byte offset 30, found 0x21"}));
}

TEST_F(PortRobustness, OversizedMessageIsRefusedBeforeReadingIt) {
  PortOptions o;
  o.max_message_size = 1000;
  Port r(o);
  r.open_at("/r", {"127.0.0.1", 0});
  auto s = net::TcpStream::connect({"127.0.0.1", r.contact().port});
  send(s, hex(kHelloW));
  read_n(s, 8);
  // Announces 8 + 100000000 bytes and sends none of them.
  send(s, hex("59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 00 e1 f5 05"
              "00 00 00 00"));
  EXPECT_TRUE(closed_by_peer(s));
  expect_still_serving(r);
  EXPECT_TRUE(logged({"/r: input from /w", "announces 100000008 bytes, more than the maximum message size of 1000"}));
}

TEST_F(PortRobustness, MalformedBottleIsDroppedAndTheConnectionKeepsWorking) {
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  auto s = net::TcpStream::connect({"127.0.0.1", r.contact().port});
  send(s, hex(kHelloW));
  read_n(s, 8);
  // A payload claiming 5 items but holding one: well framed, impossible bottle.
  send(s, hex("59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 10 00 00 00"
              "00 00 00 00 00 00 00 00 7e 44 00 01 00 01 00 00 05 00 00 00 01 00 00 00 07 00 00 00"));
  EXPECT_EQ(read_n(s, 8), hex("59 41 00 00 00 00 52 50"));
  // Same connection, good message.
  send(s, hex("59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 10 00 00 00"
              "00 00 00 00 00 00 00 00 7e 44 00 01 00 01 00 00 01 00 00 00 01 00 00 00 07 00 00 00"));
  Bottle b;
  ASSERT_TRUE(r.read(b, false, 5000ms));
  EXPECT_EQ(b.to_text(), "7");
  EXPECT_EQ(read_n(s, 8), hex("59 41 00 00 00 00 52 50"));
  EXPECT_TRUE(logged({"/r: dropped a message from /w (127.0.0.1:", "list count 5 needs at least 25 bytes"}));
}

TEST_F(PortRobustness, PeerVanishingMidMessageFreesTheInput) {
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  {
    auto s = net::TcpStream::connect({"127.0.0.1", r.contact().port});
    send(s, hex(kHelloW));
    read_n(s, 8);
    ASSERT_TRUE(eventually([&] { return r.input_names().size() == 1; }));
    send(s, hex("59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 10 00"));
  }  // closed half way through the index
  EXPECT_TRUE(eventually([&] { return r.input_names().empty(); }));
  expect_still_serving(r);
  EXPECT_TRUE(logged({"/r: input from /w", "closed the connection after 6 of 12 expected bytes"}));
}

TEST_F(PortRobustness, TruncatedHandshakeAndSilentPeerTimeOut) {
  PortOptions o;
  o.handshake_timeout = 200ms;
  Port r(o);
  r.open_at("/r", {"127.0.0.1", 0});
  auto silent = net::TcpStream::connect({"127.0.0.1", r.contact().port});
  auto half = net::TcpStream::connect({"127.0.0.1", r.contact().port});
  send(half, hex("59 41 e4 1e 00 00 52 50 40 00"));
  EXPECT_TRUE(closed_by_peer(silent));
  EXPECT_TRUE(closed_by_peer(half));
  auto liar = net::TcpStream::connect({"127.0.0.1", r.contact().port});
  send(liar, hex("59 41 e4 1e 00 00 52 50 ff ff ff 7f"));  // sender name of 2 GB
  EXPECT_TRUE(closed_by_peer(liar));
  expect_still_serving(r);
  EXPECT_TRUE(logged({"/r: rejected a connection: reading from peer 127.0.0.1:", "timed out"}));
  EXPECT_TRUE(logged({"/r: rejected a connection: handshake from 127.0.0.1:", "sender name length 2147483647 at byte offset 8 is outside 1..1000"}));
}

TEST_F(PortRobustness, StalledReaderIsDroppedWithoutStoppingOtherOutputs) {
  PortOptions o;
  o.send_timeout = 1000ms;  // generous: a loaded CI machine must not drop the good reader
  PortTable t;
  Port w(o), good;
  open_local(w, "/w", t);
  open_local(good, "/good", t);
  std::atomic<int> received{0};
  good.set_reader([&](const Bottle&, const MessageInfo&, Bottle*) { ++received; });
  // A reader that completes the handshake and then never reads again.
  net::TcpListener stall = net::TcpListener::listen({"127.0.0.1", 0});
  std::thread staller([&] {
    auto s = stall.accept(5000ms);
    ASSERT_TRUE(s.has_value());
    read_n(*s, 15);
    send(*s, hex("59 41 13 27 00 00 52 50"));
    std::this_thread::sleep_for(6s);
  });
  w.add_output(Contact{"/stall", "tcp", "127.0.0.1", stall.local().port});
  w.add_output("/good");
  std::vector<std::uint8_t> big(4u << 20, 1);
  Bottle img{Value::blob(big.data(), big.size())};
  auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 10; ++i) w.write(img);
  auto took = std::chrono::steady_clock::now() - start;
  EXPECT_LT(took, 5s);  // one send timeout, not one per message
  EXPECT_EQ(w.output_names(), std::vector<std::string>{"/good"});
  EXPECT_EQ(received.load(), 10);
  staller.join();
  EXPECT_TRUE(logged({"/w: dropping output to /stall (127.0.0.1:", "timed out"}));
}

TEST_F(PortRobustness, AnonymousSendersAreServedAndNotReplaced) {
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  r.set_reader([](const Bottle& b, const MessageInfo&, Bottle* reply) {
    if (reply) *reply = b;
  });
  auto a = net::TcpStream::connect({"127.0.0.1", r.contact().port});
  auto b = net::TcpStream::connect({"127.0.0.1", r.contact().port});
  const char anon[] = "59 41 e4 1e 00 00 52 50 09 00 00 00 61 6e 6f 6e 5f 72 70 63 00";
  send(a, hex(anon));
  read_n(a, 8);
  send(b, hex(anon));
  read_n(b, 8);
  const char rpc[] =
      "59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 10 00 00 00 00 00 00 00"
      "00 00 00 00 7e 64 00 01 00 01 00 00 01 00 00 00 01 00 00 00 2a 00 00 00";
  for (auto* s : {&a, &b}) {
    send(*s, hex(rpc));
    // The echo comes back in YARP's homogeneous form (tag 0x101), then the ack.
    EXPECT_EQ(read_n(*s, 20), hex("01 01 00 00 01 00 00 00 2a 00 00 00 59 41 00 00 00 00 52 50"));
  }
}

TEST_F(PortRobustness, NewRootedConnectionFromSameSourceReplacesTheOld) {
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  auto first = net::TcpStream::connect({"127.0.0.1", r.contact().port});
  send(first, hex(kHelloW));
  read_n(first, 8);
  ASSERT_TRUE(eventually([&] { return r.input_names().size() == 1; }));
  auto second = net::TcpStream::connect({"127.0.0.1", r.contact().port});
  send(second, hex(kHelloW));
  read_n(second, 8);
  EXPECT_TRUE(closed_by_peer(first));
  EXPECT_TRUE(eventually([&] { return r.input_names() == std::vector<std::string>{"/w"}; }));
}

TEST_F(PortRobustness, CloseSendsQuitUnregistersNothingAndJoins) {
  PortTable t;
  Port r;
  open_local(r, "/r", t);
  {
    Port w;
    open_local(w, "/w", t);
    w.add_output("/r");
    ASSERT_TRUE(eventually([&] { return r.input_names().size() == 1; }));
  }  // ~Port closes: "q" reaches /r, whose input goes away
  EXPECT_TRUE(eventually([&] { return r.input_names().empty(); }));
}

TEST_F(PortRobustness, ConnectionsBeyondTheInputLimitAreClosedAtOnce) {
  PortOptions o;
  o.max_inputs = 3;
  Port r(o);
  r.open_at("/r", {"127.0.0.1", 0});
  std::vector<net::TcpStream> held;
  for (int i = 0; i < 3; ++i) {
    held.push_back(net::TcpStream::connect({"127.0.0.1", r.contact().port}));
    send(held.back(), std::string("CONNECT t") + std::to_string(i) + "\r\n");
    read_until(held.back(), "\r\n");
  }
  auto extra = net::TcpStream::connect({"127.0.0.1", r.contact().port});
  EXPECT_TRUE(closed_by_peer(extra));
  held.clear();  // the three leave; their slots free up
  ASSERT_TRUE(eventually([&] { return r.input_names().empty(); }));
  expect_still_serving(r);
  EXPECT_TRUE(logged({"/r: refused a connection from 127.0.0.1:", "already 3 inputs (the limit)"}));
}
