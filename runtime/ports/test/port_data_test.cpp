// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Port to port: streaming, replies, envelopes, blocking reads, several inputs and outputs.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <optional>
#include <thread>

#include "robogene/testing/wire_helpers.hpp"
#include "robogene/testing/port_test_util.hpp"
#include "robogene/envelope.hpp"
#include "robogene/error.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

TEST(PortData, WriteReachesReaderCallbackWithSenderAndCarrier) {
  PortTable t;
  Port r, w;
  open_local(r, "/r", t);
  open_local(w, "/w", t);
  std::mutex m;
  std::condition_variable cv;
  std::vector<std::pair<Bottle, MessageInfo>> got;
  r.set_reader([&](const Bottle& b, const MessageInfo& info, Bottle*) {
    std::lock_guard<std::mutex> lock(m);
    got.emplace_back(b, info);
    cv.notify_all();
  });
  w.add_output("/r");
  EXPECT_EQ(w.output_names(), std::vector<std::string>{"/r"});
  ASSERT_TRUE(w.write(Bottle::from_text("1 2.5 \"hi\" [set]")));
  ASSERT_TRUE(w.write(Bottle::from_text("(nested (list 1 2)) {1 2 255}")));
  std::unique_lock<std::mutex> lock(m);
  ASSERT_TRUE(cv.wait_for(lock, 5s, [&] { return got.size() == 2; }));
  EXPECT_EQ(got[0].first.to_text(), "1 2.5 hi [set]");
  EXPECT_EQ(got[1].first.to_text(), "(nested (list 1 2)) {1 2 255}");
  EXPECT_EQ(got[0].second.from, "/w");
  EXPECT_EQ(got[0].second.carrier, "tcp");
  EXPECT_FALSE(got[0].second.reply_expected);
}

TEST(PortData, EveryCarrierDeliversTheSameBottle) {
  for (const char* carrier : {"tcp", "fast_tcp", "text", "text_ack", "udp"}) {
    PortTable t;
    Port r, w;
    open_local(r, "/r", t);
    open_local(w, "/w", t);
    w.add_output("/r", carrier);
    Bottle sent = Bottle::from_text("[set] [pos] 1 30.5 \"go left\" (10 20 30)");
    std::mutex m;
    std::condition_variable cv;
    std::optional<std::pair<Bottle, MessageInfo>> got;
    r.set_reader([&](const Bottle& b, const MessageInfo& info, Bottle*) {
      std::lock_guard<std::mutex> lock(m);
      if (!got) got.emplace(b, info);
      cv.notify_all();
    });
    std::atomic<bool> done{false};
    std::thread writer([&] {
      // udp may lose a datagram sent before the reader's socket is served: repeat until seen.
      for (int i = 0; i < 50 && !done; ++i) {
        w.write(sent);
        std::this_thread::sleep_for(20ms);
      }
    });
    {
      std::unique_lock<std::mutex> lock(m);
      ASSERT_TRUE(cv.wait_for(lock, 5s, [&] { return got.has_value(); })) << carrier;
      EXPECT_EQ(got->first, sent) << carrier;
      EXPECT_EQ(got->second.carrier, carrier);
      EXPECT_EQ(got->second.from, "/w");
    }
    done = true;
    writer.join();
  }
}

TEST(PortData, WriteWithReplyRoundTripsThroughReaderCallback) {
  PortTable t;
  Port server, client;
  open_local(server, "/motors/rpc:i", t);
  open_local(client, "/mc/rpc:o", t);
  server.set_reader([](const Bottle& b, const MessageInfo& info, Bottle* reply) {
    ASSERT_NE(reply, nullptr);
    EXPECT_TRUE(info.reply_expected);
    *reply = Bottle{Value::vocab("is"), b.get(1), Value(4), Value::vocab("ok")};
  });
  client.add_output("/motors/rpc:i");
  Bottle reply;
  ASSERT_TRUE(client.write(Bottle::from_text("[get] [axes]"), reply));
  EXPECT_EQ(reply.to_text(), "[is] [axes] 4 [ok]");
  for (int i = 0; i < 100; ++i) {
    ASSERT_TRUE(client.write(Bottle{Value(i), Value::vocab("axes")}, reply));
    EXPECT_EQ(reply.get(1).as_vocab(), vocab("axes"));
  }
}

TEST(PortData, BlockingReadAndReplyServeAnRpcClient) {
  PortTable t;
  Port server, client;
  open_local(server, "/srv", t);
  open_local(client, "/cli", t);
  client.add_output("/srv");
  std::thread s([&] {
    for (int i = 0; i < 3; ++i) {
      Bottle cmd;
      ASSERT_TRUE(server.read(cmd, true, 5000ms));
      server.reply(Bottle{Value("echo"), Value(cmd.get(0).as_int32() * 2)});
    }
  });
  for (int i = 0; i < 3; ++i) {
    Bottle reply;
    ASSERT_TRUE(client.write(Bottle{Value(i)}, reply));
    EXPECT_EQ(reply.to_text(), "echo " + std::to_string(i * 2));
  }
  s.join();
}

TEST(PortData, ReadTimesOutAndCloseWakesBlockedReader) {
  Port p;
  p.open_at("/lonely", {"127.0.0.1", 0});
  Bottle b;
  EXPECT_FALSE(p.read(b, false, 50ms));
  std::thread closer([&] {
    std::this_thread::sleep_for(50ms);
    p.close();
  });
  EXPECT_FALSE(p.read(b));
  closer.join();
}

TEST(PortData, EnvelopeTravelsAsYarpStampText) {
  // The PortCommand bytes of sniff_state.txt: ch 0, "D 1053 1795328338.10597\0".
  net::TcpListener l = net::TcpListener::listen({"127.0.0.1", 0});
  std::vector<std::uint8_t> cmd;
  std::thread peer([&] {
    auto s = l.accept(5000ms);
    ASSERT_TRUE(s.has_value());
    read_n(*s, 8 + 4 + 16);
    send(*s, hex("59 41 13 27 00 00 52 50"));
    auto idx = read_n(*s, 8 + 10 + 4 * 3);
    cmd = read_n(*s, 32);
    read_n(*s, 40);
    send(*s, hex("59 41 00 00 00 00 52 50"));
  });
  Port w;
  w.open_at("/motors/state:o", {"127.0.0.1", 0});
  w.add_output(Contact{"/sniffstate", "tcp", "127.0.0.1", l.local().port});
  w.set_envelope(Stamp{1053, 1795328338.10597}.to_text());
  Bottle v{1.0, 2.0, 3.0, 4.0};
  ASSERT_TRUE(w.write(v));
  peer.join();
  EXPECT_EQ(cmd, hex("18 00 00 00 7e 00 00 01 44 20 31 30 35 33 20 31 37 39 35 33 32 38 33 33 38"
                     "2e 31 30 35 39 37 00"));
  PortTable t;
  Port r, w2;
  open_local(r, "/r", t);
  open_local(w2, "/w", t);
  w2.add_output("/r");
  w2.set_envelope("7 12.5");
  std::thread writer([&] { w2.write(Bottle{Value(1)}); });
  Bottle b;
  MessageInfo info;
  ASSERT_TRUE(r.read(b, false, 5000ms, &info));
  writer.join();
  EXPECT_EQ(info.envelope, "7 12.5");
  auto stamp = Stamp::parse(info.envelope);
  ASSERT_TRUE(stamp.has_value());
  EXPECT_EQ(stamp->sequence, 7);
}

TEST(PortData, FanOutToSeveralReadersAndRemoveOutputAtRunTime) {
  PortTable t;
  Port w;
  open_local(w, "/w", t);
  constexpr int kReaders = 4;
  Port readers[kReaders];
  std::atomic<int> counts[kReaders] = {};
  for (int i = 0; i < kReaders; ++i) {
    open_local(readers[i], "/r" + std::to_string(i), t);
    readers[i].set_reader([&, i](const Bottle&, const MessageInfo&, Bottle*) { ++counts[i]; });
    w.add_output("/r" + std::to_string(i));
  }
  for (int k = 0; k < 10; ++k) ASSERT_TRUE(w.write(Bottle{Value(k)}));
  EXPECT_TRUE(w.remove_output("/r0"));
  EXPECT_FALSE(w.remove_output("/r0"));
  for (int k = 0; k < 5; ++k) ASSERT_TRUE(w.write(Bottle{Value(k)}));
  // tcp acks arrive only after the reader ran, so the counts are final once write returned.
  EXPECT_EQ(counts[0].load(), 10);
  for (int i = 1; i < kReaders; ++i) EXPECT_EQ(counts[i].load(), 15);
}

TEST(PortData, WriteWithoutOutputsReportsFalse) {
  Port w;
  w.open_at("/w", {"127.0.0.1", 0});
  Bottle reply;
  EXPECT_FALSE(w.write(Bottle{Value(1)}));
  EXPECT_FALSE(w.write(Bottle{Value(1)}, reply));
}

TEST(PortData, AddOutputToUnknownPortNamesIt) {
  PortTable t;
  Port w;
  open_local(w, "/w", t);
  try {
    w.add_output("/nobody");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nobody"), std::string::npos) << e.what();
  }
  EXPECT_THROW(w.add_output("nobody"), Error);
}

TEST(PortData, LargeBlobsArriveIntactThroughTheDetachedPath) {
  PortTable t;
  Port r, w;
  open_local(r, "/r", t);
  open_local(w, "/w", t);
  w.add_output("/r");
  std::vector<std::uint8_t> a(921600), b(70000), small(100, 9);
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = static_cast<std::uint8_t>(i * 13);
  for (std::size_t i = 0; i < b.size(); ++i) b[i] = static_cast<std::uint8_t>(i * 7);
  Bottle sent;
  sent.add(Value::vocab("mat"));
  sent.add(Value::blob(small.data(), small.size()));
  Bottle nested;
  nested.add(Value(1));
  nested.add(Value::blob(a.data(), a.size()));
  sent.add(Value::list(nested));
  sent.add(Value::blob(b.data(), b.size()));
  sent.add(Value::blob(std::vector<std::uint8_t>{}));
  std::thread writer([&] { w.write(sent); });
  Bottle got;
  ASSERT_TRUE(r.read(got, false, 5000ms));
  writer.join();
  EXPECT_EQ(got, sent);
}

TEST(PortData, LargeMessageThatIsNotABottleIsDroppedAndTheStreamStaysInStep) {
  PortTable t;
  Port r;
  open_local(r, "/r", t);
  auto s = net::TcpStream::connect({"127.0.0.1", r.contact().port});
  send(s, hex("59 41 e4 1e 00 00 52 50 03 00 00 00 2f 77 00"));
  read_n(s, 8);
  // 100000 payload bytes of 0x07: long enough for the walking reader, not a Bottle.
  std::vector<std::uint8_t> junk = hex("59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 a0 86 01 00 00 00 00 00 00 00 00 00 7e 44 00 01");
  junk.resize(junk.size() + 100000, 7);
  send(s, junk);
  EXPECT_EQ(read_n(s, 8), hex("59 41 00 00 00 00 52 50"));
  send(s, hex("59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 0c 00 00 00 00 00"
              "00 00 00 00 00 00 7e 44 00 01 01 01 00 00 01 00 00 00 2a 00 00 00"));
  Bottle b;
  ASSERT_TRUE(r.read(b, false, 5000ms));
  EXPECT_EQ(b.to_text(), "42");
}
