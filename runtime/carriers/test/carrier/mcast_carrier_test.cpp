// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// mcast carrier (reference section 3.6): the handshake bytes (header, name, 6-byte group), the
// group allocated by the name server and owned by the writer, one stream shared by several
// readers on loopback, and the out-of-band close.
#include <gtest/gtest.h>

#include <atomic>
#include <condition_variable>
#include <future>
#include <mutex>
#include <thread>

#include "robogene/name/local_name_server.hpp"
#include "robogene/testing/wire_helpers.hpp"
#include "robogene/carrier/registry.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/log.hpp"
#include "robogene/net/udp_socket.hpp"
#include "robogene/name_server_mcast_groups.hpp"
#include "robogene/network.hpp"
#include "robogene/port.hpp"

using namespace robogene;
using namespace robogene::carrier;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

// Collects what a port's reader gets.
struct Inbox {
  std::mutex mutex;
  std::condition_variable cv;
  std::vector<std::string> texts;
  std::vector<std::string> carriers;

  Port::Reader reader() {
    return [this](const Bottle& b, const MessageInfo& info, Bottle*) {
      std::lock_guard<std::mutex> lock(mutex);
      texts.push_back(b.to_text());
      carriers.push_back(info.carrier);
      cv.notify_all();
    };
  }
  bool wait_for(std::size_t n, std::chrono::milliseconds t = 5000ms) {
    std::unique_lock<std::mutex> lock(mutex);
    return cv.wait_for(lock, t, [&] { return texts.size() >= n; });
  }
};

// zlib's crc32, written out independently of the carrier's table-driven one.
std::uint32_t zlib_crc32(const std::uint8_t* p, std::size_t n) {
  std::uint32_t c = 0xffffffffu;
  for (std::size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
  }
  return ~c;
}

bool eventually(const std::function<bool()>& f) {
  for (int i = 0; i < 100; ++i) {
    if (f()) return true;
    std::this_thread::sleep_for(20ms);
  }
  return false;
}

}  // namespace

TEST(McastCarrier, InitiatorSendsHeaderNameAndGroupThenDatagramsToTheGroup) {
  name::LocalNameServer ns;
  auto tcp = net::TcpListener::listen({"127.0.0.1", 0});
  std::promise<std::vector<std::uint8_t>> hello;
  std::thread reader([&] {
    auto s = tcp.accept(5000ms);
    hello.set_value(read_n(*s, 8 + 4 + 3 + 6));
    // Like YARP's reader: nothing is answered, the socket is dropped once the group is joined.
  });
  ConnectContext ctx;
  ctx.sender_name = "/w";
  ctx.target_name = "/r";
  ctx.mcast_groups = name_server_mcast_groups(ns.contact());
  auto out = open_connection(tcp.local(), "mcast", ctx);
  reader.join();
  auto got = hello.get_future().get();
  EXPECT_EQ(std::vector<std::uint8_t>(got.begin(), got.begin() + 15), hex("59 41 62 1e 00 00 52 50 03 00 00 00 2f 77 00"));
  // The group is what the name server registered for it, and /w does not exist there, so the
  // group is the server's first mcast allocation.
  auto regs = ns.client().request("NAME_SERVER list\n");
  std::string group_line;
  for (const auto& l : regs) {
    if (l.find("type mcast") != std::string::npos) group_line = l;
  }
  ASSERT_FALSE(group_line.empty());
  auto reg = NameClient::parse_registration(group_line);
  ASSERT_TRUE(reg.has_value());
  EXPECT_EQ(reg->host.rfind("224.1.", 0), 0u) << reg->host;
  unsigned a, b, c, d;
  ASSERT_EQ(std::sscanf(reg->host.c_str(), "%u.%u.%u.%u", &a, &b, &c, &d), 4);
  EXPECT_EQ(got[15], a);
  EXPECT_EQ(got[16], b);
  EXPECT_EQ(got[17], c);
  EXPECT_EQ(got[18], d);
  EXPECT_EQ(got[19] * 256 + got[20], reg->port);
  out->close();
  // The last sender gone, the group is unregistered.
  bool still = false;
  for (const auto& l : ns.client().request("NAME_SERVER list\n")) still |= l.find("type mcast") != std::string::npos;
  EXPECT_FALSE(still);
}

namespace {

// The carrier gets its group from whoever connects (ports pass their name server's): here an
// allocator of the test's own, which sees every request and every release.
struct RecordingAllocator : McastGroupAllocator {
  std::optional<Grant> grant;
  std::vector<std::string> calls;
  std::optional<Grant> allocate(const std::string& sender, net::Millis) override {
    calls.push_back("allocate " + sender);
    return grant;
  }
  void release(const Grant& g, net::Millis) noexcept override { calls.push_back("release " + g.registration); }
};

// Connects an mcast output from `sender` to a listener that reads the hello; returns its bytes.
std::vector<std::uint8_t> mcast_hello(const std::string& sender, std::shared_ptr<McastGroupAllocator> groups,
                                      std::unique_ptr<OutboundConnection>& out) {
  auto tcp = net::TcpListener::listen({"127.0.0.1", 0});
  std::promise<std::vector<std::uint8_t>> hello;
  std::thread reader([&] {
    auto s = tcp.accept(5000ms);
    hello.set_value(read_n(*s, 8 + 4 + sender.size() + 1 + 6));
  });
  ConnectContext ctx;
  ctx.sender_name = sender;
  ctx.target_name = "/r";
  ctx.mcast_groups = std::move(groups);
  out = open_connection(tcp.local(), "mcast", ctx);
  reader.join();
  return hello.get_future().get();
}

}  // namespace

TEST(McastCarrier, TheGroupComesFromTheInjectedAllocatorAndGoesBackWithTheLastOutput) {
  auto groups = std::make_shared<RecordingAllocator>();
  groups->grant = McastGroupAllocator::Grant{{"224.1.7.9", 10123}, "/tmp/port/7"};
  std::unique_ptr<OutboundConnection> out;
  auto got = mcast_hello("/wa", groups, out);
  // 224.1.7.9, port 10123 = 0x278b big-endian.
  EXPECT_EQ(std::vector<std::uint8_t>(got.end() - 6, got.end()), hex("e0 01 07 09 27 8b"));
  EXPECT_EQ(groups->calls, std::vector<std::string>{"allocate /wa"});
  out->close();
  out.reset();
  EXPECT_EQ(groups->calls, (std::vector<std::string>{"allocate /wa", "release /tmp/port/7"}));
}

TEST(McastCarrier, WithoutAGroupTheWriterUsesYarpsFallbackGroup) {
  log::set_level(log::Level::Error);
  auto refusing = std::make_shared<RecordingAllocator>();  // hands out nothing
  std::unique_ptr<OutboundConnection> out;
  auto got = mcast_hello("/wb", refusing, out);
  EXPECT_EQ(std::vector<std::uint8_t>(got.end() - 6, got.end()), hex("e0 03 01 01 2a f8"));  // 224.3.1.1:11000
  out.reset();
  EXPECT_EQ(refusing->calls, std::vector<std::string>{"allocate /wb"});  // nothing to give back
  std::unique_ptr<OutboundConnection> none;
  got = mcast_hello("/wc", nullptr, none);  // no allocator at all
  EXPECT_EQ(std::vector<std::uint8_t>(got.end() - 6, got.end()), hex("e0 03 01 01 2a f8"));
  log::set_level(log::Level::Warn);
}

TEST(McastCarrier, AcceptorReadsTheGroupJoinsItAndHangsUp) {
  log::set_level(log::Level::Off);
  auto tcp = net::TcpListener::listen({"127.0.0.1", 0});
  std::future<std::unique_ptr<InboundConnection>> accepted = std::async(std::launch::async, [&] {
    auto s = tcp.accept(5000ms);
    return accept_connection(std::move(*s), AcceptContext{});
  });
  auto client = net::TcpStream::connect(tcp.local());
  // 224.1.9.9, port 256 * 0x2a + 0x11 = 10769
  send(client, hex("59 41 62 1e 00 00 52 50 03 00 00 00 2f 77 00 e0 01 09 09 2a 11"));
  auto conn = accepted.get();
  EXPECT_EQ(conn->remote_name(), "/w");
  EXPECT_EQ(conn->carrier_name(), "mcast");
  char c;
  client.set_read_timeout(2000ms);
  EXPECT_EQ(client.read_some(&c, 1), 0u);  // hung up without a word
  // A datagram to the group reaches the reader.
  auto message = hex("59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 0c 00 00 00"
                     "00 00 00 00 00 00 00 00 7e 44 00 01 01 01 00 00 01 00 00 00 2a 00 00 00");
  std::vector<std::uint8_t> d(8);
  put_int32(d.data(), static_cast<std::int32_t>(zlib_crc32(message.data(), message.size())));
  d.insert(d.end(), message.begin(), message.end());
  net::UdpSocket sender = net::UdpSocket::bind({"127.0.0.1", 0});
  std::thread pump([&] {
    // Multicast from 127.0.0.1 reaches the group through loopback.
    for (int i = 0; i < 3; ++i) {
      sender.send_to({"224.1.9.9", 10769}, d.data(), d.size());
      std::this_thread::sleep_for(50ms);
    }
  });
  InboundMessage m;
  ASSERT_TRUE(conn->read(m));
  pump.join();
  EXPECT_EQ(m.bottle().to_text(), "42");
  conn->interrupt();
  log::set_level(log::Level::Warn);
}

TEST(McastCarrier, AcceptorRefusesAGroupThatIsNotMulticast) {
  log::set_level(log::Level::Off);
  auto tcp = net::TcpListener::listen({"127.0.0.1", 0});
  std::future<std::string> error = std::async(std::launch::async, [&] {
    auto s = tcp.accept(5000ms);
    try {
      accept_connection(std::move(*s), AcceptContext{});
    } catch (const NetworkError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  });
  auto client = net::TcpStream::connect(tcp.local());
  send(client, hex("59 41 62 1e 00 00 52 50 03 00 00 00 2f 77 00 0a 00 00 01 2a 11"));  // 10.0.0.1
  EXPECT_NE(error.get().find("10.0.0.1:10769 is not a multicast group"), std::string::npos);
  log::set_level(log::Level::Warn);
}

TEST(McastCarrier, SeveralReadersShareOneStreamAndTheWriterClosesThemOutOfBand) {
  name::LocalNameServer ns;
  Port w, r1, r2, r3;
  Inbox in1, in2, in3;
  r1.set_reader(in1.reader());
  r2.set_reader(in2.reader());
  r3.set_reader(in3.reader());
  w.open("/mw", ns.client());
  r1.open("/mr1", ns.client());
  r2.open("/mr2", ns.client());
  r3.open("/mr3", ns.client());
  w.add_output("/mr1", "mcast");
  w.add_output("/mr2", "mcast");
  w.add_output("/mr3", "mcast");
  for (Port* r : {&r1, &r2, &r3}) {
    ASSERT_TRUE(eventually([&] { return r->input_names() == std::vector<std::string>{"/mw"}; }));
  }
  // The writer owns one group at the name server.
  auto owns = ns.client().request("NAME_SERVER get /mw owns\n");
  ASSERT_EQ(owns.size(), 1u);
  EXPECT_NE(owns[0].find("/tmp/port/"), std::string::npos) << owns[0];
  std::vector<std::uint8_t> pixels(300000);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<std::uint8_t>(i * 7);
  for (int i = 0; i < 5; ++i) {
    Bottle b{Value(i), Value("tick")};
    ASSERT_TRUE(w.write(b));
    std::this_thread::sleep_for(10ms);
  }
  Bottle image{Value("image"), Value::blob(pixels.data(), pixels.size())};
  ASSERT_TRUE(w.write(image));
  for (Inbox* in : {&in1, &in2, &in3}) {
    ASSERT_TRUE(in->wait_for(6));
    std::lock_guard<std::mutex> lock(in->mutex);
    // Each reader got each message exactly once, in order, although there were three outputs.
    ASSERT_EQ(in->texts.size(), 6u);
    for (int i = 0; i < 5; ++i) EXPECT_EQ(in->texts[i], std::to_string(i) + " tick");
    EXPECT_EQ(in->texts[5], image.to_text());
    EXPECT_EQ(in->carriers[0], "mcast");
  }
  // Admin [list] shows the connection as connectionless mcast.
  Bottle route = network::admin(w.contact(), Bottle::from_text("[list] [out] \"/mr2\""));
  EXPECT_EQ(route.to_text(), "(from \"/mw\") (to \"/mr2\") (carrier mcast) (connectionless 1)");
  // Removing one output ends that reader's input out of band; the others keep receiving.
  EXPECT_TRUE(w.remove_output("/mr2"));
  EXPECT_TRUE(eventually([&] { return r2.input_names().empty(); }));
  ASSERT_TRUE(w.write(Bottle{Value("after")}));
  ASSERT_TRUE(in1.wait_for(7));
  ASSERT_TRUE(in3.wait_for(7));
  EXPECT_FALSE(in2.wait_for(7, 300ms));
  // Closing the writer ends the remaining inputs and drops the group with the owner.
  w.close();
  EXPECT_TRUE(eventually([&] { return r1.input_names().empty() && r3.input_names().empty(); }));
  bool group_left = false;
  for (const auto& l : ns.client().request("NAME_SERVER list\n")) group_left |= l.find("type mcast") != std::string::npos;
  EXPECT_FALSE(group_left);
}

TEST(McastCarrier, UnregisteringTheOwnerDropsItsGroupAtTheNameServer) {
  name::LocalNameServer ns;
  auto names = ns.client();
  names.register_name("/owner");
  auto lines = names.request("NAME_SERVER register ... mcast ... ...\r\n");
  ASSERT_FALSE(lines.empty());
  auto group = NameClient::parse_registration(lines[0]);
  ASSERT_TRUE(group.has_value());
  EXPECT_EQ(group->carrier, "mcast");
  names.set_property("/owner", "owns", {group->name});
  ASSERT_TRUE(names.query(group->name).has_value());
  names.unregister("/owner");
  EXPECT_FALSE(names.query(group->name).has_value());
}
