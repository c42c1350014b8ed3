// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <thread>

#include "robogene/testing/port_test_util.hpp"
#include "robogene/buffered_port.hpp"
#include "robogene/error.hpp"
#include "robogene/rpc.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

TEST(BufferedPort, LatestOnlyKeepsTheNewestAndCountsTheRest) {
  PortTable t;
  BufferedPort in(BufferPolicy::LatestOnly);
  Port out;
  open_local(in.port(), "/in", t);
  open_local(out, "/out", t);
  out.add_output("/in");
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(out.write(Bottle{Value(i)}));
  // tcp acks come after the message was buffered, so all five are in.
  EXPECT_EQ(in.pending(), 1u);
  EXPECT_EQ(in.dropped(), 4u);
  auto b = in.poll();
  ASSERT_TRUE(b.has_value());
  EXPECT_EQ(b->to_text(), "4");
  EXPECT_FALSE(in.poll().has_value());
}

TEST(BufferedPort, StrictKeepsEveryMessageInOrderUpToItsBound) {
  PortTable t;
  BufferedPort in(BufferPolicy::Strict, 3);
  BufferedPort out;
  open_local(in.port(), "/in", t);
  open_local(out.port(), "/out", t);
  out.port().add_output("/in");
  for (int i = 0; i < 5; ++i) {
    out.prepare().add(Value(i));
    ASSERT_TRUE(out.write());
  }
  EXPECT_EQ(in.dropped(), 2u);
  for (int i = 2; i < 5; ++i) {
    auto b = in.read(1000ms);
    ASSERT_TRUE(b.has_value());
    EXPECT_EQ(b->get(0).as_int32(), i);
  }
  EXPECT_FALSE(in.read(20ms).has_value());
}

TEST(BufferedPort, BlockingReadWakesOnArrivalAndOnClose) {
  PortTable t;
  BufferedPort in;
  Port out;
  open_local(in.port(), "/in", t);
  open_local(out, "/out", t);
  out.add_output("/in");
  std::thread w([&] {
    std::this_thread::sleep_for(30ms);
    out.write(Bottle::from_text("hello"));
  });
  MessageInfo info;
  auto b = in.read(net::kNoTimeout, &info);
  w.join();
  ASSERT_TRUE(b.has_value());
  EXPECT_EQ(b->to_text(), "hello");
  EXPECT_EQ(info.from, "/out");
  std::thread c([&] {
    std::this_thread::sleep_for(30ms);
    in.close();
  });
  EXPECT_FALSE(in.read().has_value());
  c.join();
}

TEST(BufferedPort, CallbackRunsForEveryMessage) {
  PortTable t;
  BufferedPort in;
  Port out;
  open_local(in.port(), "/in", t);
  open_local(out, "/out", t);
  std::vector<std::string> seen;
  in.set_callback([&](const Bottle& b, const MessageInfo&) { seen.push_back(b.to_text()); });
  out.add_output("/in");
  out.write(Bottle::from_text("a"));
  out.write(Bottle::from_text("b"));
  EXPECT_EQ(seen, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(in.pending(), 0u);
}

TEST(Rpc, ClientServerWithHandlerAndWithReadReply) {
  PortTable t;
  RpcServer server;
  RpcClient client;
  open_local(server.port(), "/motors/rpc:i", t);
  open_local(client.port(), "/mc/rpc:o", t);
  server.serve([](const Bottle& req, const MessageInfo& info) {
    EXPECT_EQ(info.from, "/mc/rpc:o");
    if (req.get(0).as_vocab() == vocab("get") && req.get(1).as_vocab() == vocab("prot")) {
      return Bottle::from_text("[prot] 1 9 0 [ok]");
    }
    return Bottle::from_text("[nak]");
  });
  client.connect("/motors/rpc:i");
  EXPECT_EQ(client.call(Bottle::from_text("[get] [prot]")).to_text(), "[prot] 1 9 0 [ok]");
  EXPECT_EQ(client.call(Bottle::from_text("[bogus]")).to_text(), "[nak]");

  RpcServer manual;
  open_local(manual.port(), "/manual", t);
  std::thread s([&] {
    Bottle req;
    ASSERT_TRUE(manual.read(req, 5000ms));
    manual.reply(Bottle{Value("got"), Value(static_cast<std::int32_t>(req.size()))});
  });
  client.connect("/manual");
  EXPECT_EQ(client.call(Bottle::from_text("a b c")).to_text(), "got 3");
  s.join();
}

TEST(Rpc, CallWithoutServerOrAfterItDiedNamesTheProblem) {
  PortTable t;
  RpcClient client;
  open_local(client.port(), "/c", t);
  EXPECT_THROW(client.call(Bottle{Value(1)}), NetworkError);
  auto server = std::make_unique<RpcServer>();
  open_local(server->port(), "/s", t);
  server->serve([](const Bottle& b, const MessageInfo&) { return b; });
  client.connect("/s");
  EXPECT_EQ(client.call(Bottle{Value(1)}).to_text(), "1");
  server.reset();
  try {
    client.call(Bottle{Value(1)});
    FAIL();
  } catch (const NetworkError& e) {
    EXPECT_NE(std::string(e.what()).find("/s"), std::string::npos) << e.what();
  }
}

TEST(Rpc, UnopenedPortWritesAsAnonymousSender) {
  Port server;
  server.open_at("/srv", {"127.0.0.1", 0});
  server.set_reader([](const Bottle&, const MessageInfo& info, Bottle* reply) {
    if (reply) *reply = Bottle{Value(info.from)};
  });
  Port anon;
  anon.add_output(server.contact());
  Bottle reply;
  ASSERT_TRUE(anon.write(Bottle{Value(1)}, reply));
  EXPECT_EQ(reply.to_text(), "anon_rpc");
  EXPECT_FALSE(anon.is_open());
}
