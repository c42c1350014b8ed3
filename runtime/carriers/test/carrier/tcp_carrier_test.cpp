// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// tcp / fast_tcp against the bytes of real YARP traffic (yarp-captures/*.flows.txt).
#include <gtest/gtest.h>

#include <future>
#include <thread>

#include "robogene/testing/wire_helpers.hpp"
#include "robogene/carrier/registry.hpp"
#include "robogene/error.hpp"

using namespace robogene;
using namespace robogene::carrier;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

// `yarp write /w` to /r, from write_connect_read.flows.txt.
const char kHandshakeW[] = "59 41 e4 1e 00 00 52 50 03 00 00 00 2f 77 00";
const char kMessage1[] =
    "59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 2e 00 00 00 00 00 00 00 00 00"
    "00 00 7e 44 00 01 00 01 00 00 04 00 00 00 01 00 00 00 01 00 00 00 0a 00 00 00 00 00 00 00"
    "00 00 04 40 04 00 00 00 02 00 00 00 68 69 09 00 00 00 73 65 74 00";
const char kQuit[] =
    "59 41 0a 00 00 00 52 50 01 01 ff ff ff ff ff ff ff ff 0a 00 00 00 00 00 00 00 02 00 00 00"
    "7e 00 00 01 71 00";
const char kAck[] = "59 41 00 00 00 00 52 50";

struct Server {
  net::TcpListener listener = net::TcpListener::listen({"127.0.0.1", 0});
  std::future<std::unique_ptr<InboundConnection>> accepted;
  AcceptContext ctx;

  void start() {
    accepted = std::async(std::launch::async, [this] {
      auto s = listener.accept(5000ms);
      if (!s) throw NetworkError("no connection");
      return accept_connection(std::move(*s), ctx);
    });
  }
};

}  // namespace

TEST(TcpCarrier, AcceptsCapturedHandshakeAndRepliesWithItsPortNumber) {
  Server srv;
  srv.start();
  auto client = net::TcpStream::connect(srv.listener.local());
  send(client, hex(kHandshakeW));
  auto conn = srv.accepted.get();
  EXPECT_EQ(conn->remote_name(), "/w");
  EXPECT_EQ(conn->carrier_name(), "tcp");
  auto reply = read_n(client, 8);
  int port = srv.listener.local().port;
  EXPECT_EQ(reply, (std::vector<std::uint8_t>{'Y', 'A', static_cast<std::uint8_t>(port & 0xff),
                                               static_cast<std::uint8_t>(port >> 8), 0, 0, 'R', 'P'}));
}

TEST(TcpCarrier, ReadsCapturedMessageAndAcksExactly) {
  Server srv;
  srv.start();
  auto client = net::TcpStream::connect(srv.listener.local());
  send(client, hex(kHandshakeW));
  auto conn = srv.accepted.get();
  read_n(client, 8);
  send(client, hex(kMessage1));
  InboundMessage m;
  ASSERT_TRUE(conn->read(m));
  EXPECT_EQ(m.key, 'D');
  EXPECT_FALSE(m.reply_expected);
  EXPECT_EQ(m.bottle().to_text(), "1 2.5 hi [set]");
  conn->finish();
  EXPECT_EQ(read_n(client, 8), hex(kAck));
  send(client, hex(kQuit));
  ASSERT_TRUE(conn->read(m));
  EXPECT_EQ(m.key, 'q');
  conn->finish();
  EXPECT_EQ(read_n(client, 8), hex(kAck));
  client.close();
  EXPECT_FALSE(conn->read(m));
}

TEST(TcpCarrier, InitiatorSendsTheBytesYarpWriteSends) {
  net::TcpListener l = net::TcpListener::listen({"127.0.0.1", 0});
  std::vector<std::uint8_t> seen;
  std::thread peer([&] {
    auto s = l.accept(5000ms);
    ASSERT_TRUE(s.has_value());
    seen = read_n(*s, 15);
    send(*s, hex("59 41 13 27 00 00 52 50"));
    auto msg = read_n(*s, 84);
    seen.insert(seen.end(), msg.begin(), msg.end());
    send(*s, hex(kAck));
    auto q = read_n(*s, 36);
    seen.insert(seen.end(), q.begin(), q.end());
    send(*s, hex(kAck));
  });
  ConnectContext ctx;
  ctx.sender_name = "/w";
  ctx.target_name = "/r";
  auto out = open_connection(l.local(), "tcp", ctx);
  Bottle b = Bottle::from_text("1 2.5 \"hi\" [set]");
  OutboundMessage m;
  m.key = 'D';
  m.bottle = &b;
  out->send(m);
  out->close();
  peer.join();
  auto expected = hex(kHandshakeW);
  auto m1 = hex(kMessage1), q = hex(kQuit);
  expected.insert(expected.end(), m1.begin(), m1.end());
  expected.insert(expected.end(), q.begin(), q.end());
  EXPECT_EQ(seen, expected);
}

TEST(TcpCarrier, RpcRequestGetsRawReplyThenAckAsInRpcMotorsCapture) {
  // The request bytes of `yarp rpc` (`[get] [axes]` as strings) and the device's reply.
  const char request[] =
      "59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 17 00 00 00 00 00 00 00 00 00"
      "00 00 7e 64 00 01 04 01 00 00 02 00 00 00 03 00 00 00 67 65 74 04 00 00 00 61 78 65 73";
  const char reply[] =
      "00 01 00 00 07 00 00 00 09 00 00 00 69 73 00 00 04 00 00 00 04 00 00 00 61 78 65 73 01 00"
      "00 00 04 00 00 00 09 00 00 00 74 73 74 61 01 00 00 00 00 00 00 00 0a 00 00 00 4a 7c ad 51"
      "a2 c0 da 41 09 00 00 00 6f 6b 00 00";
  // Server side: our acceptor decodes the request and writes reply + ack in one go.
  Server srv;
  srv.start();
  auto client = net::TcpStream::connect(srv.listener.local());
  send(client, hex("59 41 e4 1e 00 00 52 50 09 00 00 00 61 6e 6f 6e 5f 72 70 63 00"));
  auto conn = srv.accepted.get();
  EXPECT_EQ(conn->remote_name(), "anon_rpc");
  read_n(client, 8);
  send(client, hex(request));
  InboundMessage m;
  ASSERT_TRUE(conn->read(m));
  EXPECT_EQ(m.key, 'd');
  EXPECT_TRUE(m.reply_expected);
  EXPECT_EQ(m.bottle().to_text(), "get axes");
  conn->reply(Bottle::from_bytes(hex(reply)));
  conn->finish();
  auto expected = hex(reply);
  auto ack = hex(kAck);
  expected.insert(expected.end(), ack.begin(), ack.end());
  EXPECT_EQ(read_n(client, expected.size()), expected);

  // Client side: our initiator reads the captured raw reply and the ack.
  net::TcpListener l = net::TcpListener::listen({"127.0.0.1", 0});
  std::thread device([&] {
    auto s = l.accept(5000ms);
    ASSERT_TRUE(s.has_value());
    read_n(*s, 8 + 4 + 9);
    send(*s, hex("59 41 14 27 00 00 52 50"));
    read_n(*s, hex(request).size());
    auto out = hex(reply);
    out.insert(out.end(), ack.begin(), ack.end());
    send(*s, out);
  });
  ConnectContext ctx;
  ctx.sender_name = "anon_rpc";
  auto rpc = open_connection(l.local(), "tcp", ctx);
  Bottle cmd = Bottle::from_text("get axes");
  Bottle got;
  OutboundMessage req;
  req.key = 'd';
  req.bottle = &cmd;
  rpc->send(req, &got);
  device.join();
  EXPECT_EQ(got.to_text(), "[is] axes 4 [tsta] 0 1795328326.71071100235 [ok]");
}

TEST(TcpCarrier, ImageGoesOutWithYarpsBlockSplitAndNoPixelCopy) {
  // sniff_image.txt: blocks [8, 60, 921600, 0].
  std::vector<std::uint8_t> pixels(921600, 7);
  Bottle img;
  img.add(Value::vocab("mat"));
  img.add(Value::vocab("rgb"));
  img.add(Value::list(Bottle{3, 921600, 65544, 640, 480}));
  img.add(Value::blob(pixels.data(), pixels.size()));
  net::TcpListener l = net::TcpListener::listen({"127.0.0.1", 0});
  std::vector<std::uint8_t> head;
  std::vector<std::uint8_t> body;
  std::thread peer([&] {
    auto s = l.accept(5000ms);
    ASSERT_TRUE(s.has_value());
    read_n(*s, 8 + 4 + 16);
    send(*s, hex("59 41 13 27 00 00 52 50"));
    head = read_n(*s, 34);
    body = read_n(*s, 8 + 60 + 921600);
    send(*s, hex(kAck));
  });
  ConnectContext ctx;
  ctx.sender_name = "/bench/stream:o";
  auto out = open_connection(l.local(), "tcp", ctx);
  OutboundMessage m;
  m.bottle = &img;
  out->send(m);
  peer.join();
  EXPECT_EQ(head, hex("59 41 0a 00 00 00 52 50 03 01 ff ff ff ff ff ff ff ff 08 00 00 00 3c 00 00"
                      "00 00 10 0e 00 00 00 00 00"));
  EXPECT_EQ(std::vector<std::uint8_t>(body.begin() + 8, body.begin() + 68),
            hex("00 01 00 00 04 00 00 00 09 00 00 00 6d 61 74 00 09 00 00 00 72 67 62 00 01 01 00"
                "00 05 00 00 00 03 00 00 00 00 10 0e 00 08 00 01 00 80 02 00 00 e0 01 00 00 0c 00"
                "00 00 00 10 0e 00"));
  EXPECT_EQ(body.back(), 7);
}

TEST(TcpCarrier, FastTcpSendsNoAcks) {
  Server srv;
  srv.start();
  auto client = net::TcpStream::connect(srv.listener.local());
  send(client, hex("59 41 64 1e 00 00 52 50 03 00 00 00 2f 77 00"));
  auto conn = srv.accepted.get();
  EXPECT_EQ(conn->carrier_name(), "fast_tcp");
  read_n(client, 8);
  send(client, hex(kMessage1));
  InboundMessage m;
  ASSERT_TRUE(conn->read(m));
  conn->finish();
  client.set_read_timeout(100ms);
  char c;
  EXPECT_THROW(client.read_exact(&c, 1), NetworkError);
}

TEST(CarrierDetection, UnknownHeaderGetsYarpsHelpTextAndAClose) {
  Server srv;
  srv.start();
  auto client = net::TcpStream::connect(srv.listener.local());
  send(client, std::string("HELLO TH"));
  try {
    srv.accepted.get();
    FAIL();
  } catch (const NetworkError& e) {
    EXPECT_NE(std::string(e.what()).find("48 45 4c 4c 4f 20 54 48"), std::string::npos) << e.what();
  }
  std::string text = read_until(client, "\n* Then");
  EXPECT_EQ(text.rfind("* Error. Protocol not found.\r\n", 0), 0u) << text;
  EXPECT_NE(text.find("try typing \"CONNECT foo\""), std::string::npos);
}

TEST(CarrierDetection, NewCarrierPlugsInThroughTheRegistry) {
  // A carrier that only exists in this test: header "PINGPONG", answers the first line.
  struct Echo final : InboundConnection {
    std::unique_ptr<Link> link;
    std::string name = "pingpong", remote = "pinger";
    explicit Echo(std::unique_ptr<Link> l) : link(std::move(l)) {}
    const std::string& carrier_name() const override { return name; }
    const std::string& remote_name() const override { return remote; }
    std::string peer_text() const override { return link->stream.peer_text(); }
    bool is_text() const override { return true; }
    void interrupt() noexcept override {}
    bool read(InboundMessage& m) override {
      m.command = link->reader.read_line(100);
      m.key = 'd';
      return true;
    }
    void reply(const Bottle&) override {}
    void reply_raw(const void* d, std::size_t n) override { link->stream.write_all(d, n); }
    void finish() override {}
    std::unique_ptr<OutboundConnection> reverse() override { return nullptr; }
  };
  struct PingPong final : Carrier {
    std::string name() const override { return "pingpong"; }
    Header header() const override { return {'P', 'I', 'N', 'G', 'P', 'O', 'N', 'G'}; }
    bool matches(const Header& h) const override { return h == header(); }
    std::unique_ptr<InboundConnection> accept(std::unique_ptr<Link> l, const AcceptContext&) const override {
      return std::make_unique<Echo>(std::move(l));
    }
    std::unique_ptr<OutboundConnection> connect(std::unique_ptr<Link>, const ConnectContext&) const override {
      throw Error("inbound only");
    }
  };
  CarrierRegistry::global().add(std::make_shared<PingPong>());
  Server srv;
  srv.start();
  auto client = net::TcpStream::connect(srv.listener.local());
  send(client, std::string("PINGPONGhello\n"));
  auto conn = srv.accepted.get();
  InboundMessage m;
  ASSERT_TRUE(conn->read(m));
  EXPECT_EQ(m.command, "hello");
  conn->reply_raw("pong\n", 5);
  EXPECT_EQ(read_until(client, "\n"), "pong\n");
}
