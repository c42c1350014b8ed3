// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// shmem carrier: the handshake bytes and the segment's lifetime, ports streaming images larger
// than a ring and answering RPCs through shared memory, and what happens on garbage, on a peer
// that vanishes mid-message and on a YARP-style (ACE) answer. The ring-level tests use the
// carrier's private segment class to play a misbehaving peer.
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <fcntl.h>

#include <future>
#include <thread>

#include "../../src/carrier/shm_segment.hpp"
#include "robogene/testing/wire_helpers.hpp"
#include "robogene/testing/port_test_util.hpp"
#include "robogene/carrier/registry.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/log.hpp"

using namespace robogene;
using namespace robogene::carrier;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

bool shm_exists(const std::string& name) {
  int fd = ::shm_open(name.c_str(), O_RDONLY, 0);
  if (fd < 0) return false;
  ::close(fd);
  return true;
}

// A raw initiator: sends the header and name, reads the segment name, maps it, confirms.
struct RawInitiator {
  net::TcpStream tcp;
  std::string segment;
  std::unique_ptr<detail::ShmSegment> seg;

  RawInitiator(const net::Endpoint& at, bool confirm = true) : tcp(net::TcpStream::connect(at)) {
    send(tcp, hex("59 41 6f 1e 00 00 52 50 03 00 00 00 2f 77 00"));
    auto n = read_n(tcp, 8);
    auto len = read_yarp_number(n.data());
    if (!len) throw Error("no YA <n> RP");
    auto name = read_n(tcp, static_cast<std::size_t>(*len));
    segment.assign(name.begin(), name.end() - 1);
    seg = detail::ShmSegment::open(segment);
    if (confirm) send(tcp, hex("59 41 00 00 00 00 52 50"));
  }
  void write(const std::vector<std::uint8_t>& bytes) {
    detail::ShmStream out(*seg, 0, "test", [] { return true; });
    out.write(bytes.data(), bytes.size(), 1000ms);
  }
};

std::future<std::unique_ptr<InboundConnection>> accept_one(net::TcpListener& l) {
  return std::async(std::launch::async, [&l] {
    auto s = l.accept(5000ms);
    AcceptContext ctx;
    ctx.handshake_timeout = 1000ms;
    return accept_connection(std::move(*s), ctx);
  });
}

}  // namespace

TEST(ShmemCarrier, HandshakeNamesASegmentThatIsUnlinkedOnceMapped) {
  auto tcp = net::TcpListener::listen({"127.0.0.1", 0});
  auto accepted = accept_one(tcp);
  RawInitiator raw(tcp.local(), false);
  EXPECT_EQ(raw.segment.rfind("/robogene-shmem-", 0), 0u) << raw.segment;
  EXPECT_TRUE(shm_exists(raw.segment));
  send(raw.tcp, hex("59 41 00 00 00 00 52 50"));
  auto conn = accepted.get();
  EXPECT_EQ(conn->carrier_name(), "shmem");
  EXPECT_EQ(conn->remote_name(), "/w");
  EXPECT_FALSE(shm_exists(raw.segment));  // nothing is left behind, whatever happens next
  // A tcp-style message through the ring reaches the acceptor.
  raw.write(hex("59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 0c 00 00 00"
                "00 00 00 00 00 00 00 00 7e 44 00 01 01 01 00 00 01 00 00 00 2a 00 00 00"));
  InboundMessage m;
  ASSERT_TRUE(conn->read(m));
  EXPECT_EQ(m.bottle().to_text(), "42");
}

TEST(ShmemCarrier, InitiatorThatNeverConfirmsIsRefusedAndTheSegmentRemoved) {
  log::set_level(log::Level::Off);
  auto tcp = net::TcpListener::listen({"127.0.0.1", 0});
  auto accepted = accept_one(tcp);
  RawInitiator raw(tcp.local(), false);
  EXPECT_THROW(accepted.get(), NetworkError);
  EXPECT_FALSE(shm_exists(raw.segment));
  log::set_level(log::Level::Warn);
}

TEST(ShmemCarrier, GarbageInTheRingIsAParseErrorNamingTheBytes) {
  auto tcp = net::TcpListener::listen({"127.0.0.1", 0});
  auto accepted = accept_one(tcp);
  RawInitiator raw(tcp.local());
  auto conn = accepted.get();
  raw.write(bytes("GARBAGE!"));
  InboundMessage m;
  try {
    conn->read(m);
    FAIL() << "garbage was accepted";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("expected index header"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("47 41 52 42"), std::string::npos) << e.what();
  }
}

TEST(ShmemCarrier, PeerVanishingMidMessageIsNoticedAndBetweenMessagesIsAnEnd) {
  auto tcp = net::TcpListener::listen({"127.0.0.1", 0});
  {
    auto accepted = accept_one(tcp);
    RawInitiator raw(tcp.local());
    auto conn = accepted.get();
    raw.write(hex("59 41 0a 00 00 00 52 50 02 01 ff ff"));  // a message cut short
    raw.tcp.close();                                      // ... and its process gone
    InboundMessage m;
    try {
      conn->read(m);
      FAIL() << "a truncated message was accepted";
    } catch (const NetworkError& e) {
      EXPECT_NE(std::string(e.what()).find("vanished in the middle of a message"), std::string::npos) << e.what();
    }
  }
  {
    auto accepted = accept_one(tcp);
    RawInitiator raw(tcp.local());
    auto conn = accepted.get();
    raw.tcp.close();
    InboundMessage m;
    EXPECT_FALSE(conn->read(m));  // gone between messages: a plain end, like tcp's EOF
  }
}

TEST(ShmemCarrier, YarpsAceAnswerIsRefusedWithAClearMessage) {
  auto tcp = net::TcpListener::listen({"127.0.0.1", 0});
  std::thread yarp_like([&] {
    auto s = tcp.accept(5000ms);
    read_n(*s, 15);
    send(*s, hex("59 41 39 30 00 00 52 50"));  // YARP: "connect again to port 12345"
    read_until(*s, "never");
  });
  ConnectContext ctx;
  ctx.sender_name = "/w";
  ctx.target_name = "/yarp/r";
  try {
    open_connection(tcp.local(), "shmem", ctx);
    FAIL() << "connected";
  } catch (const NetworkError& e) {
    EXPECT_NE(std::string(e.what()).find("YARP's ACE shmem"), std::string::npos) << e.what();
  }
  yarp_like.join();
}

TEST(ShmemCarrier, PortsStreamImagesBiggerThanTheRingAndAnswerRpcs) {
  PortTable t;
  Port w, r;
  open_local(w, "/sw", t);
  open_local(r, "/sr", t);
  std::mutex mutex;
  std::condition_variable cv;
  std::vector<std::size_t> sizes;
  std::vector<bool> intact;
  r.set_reader([&](const Bottle& b, const MessageInfo& info, Bottle* reply) {
    if (reply) {
      *reply = Bottle{Value("got"), Value(info.carrier)};
      return;
    }
    const Value& blob = b[1];
    auto data = blob.as_blob();
    bool ok = true;
    for (std::size_t i = 0; i < data.size(); i += 4093) ok &= data[i] == static_cast<std::uint8_t>(i * 31 + b[0].as_int32());
    std::lock_guard<std::mutex> lock(mutex);
    sizes.push_back(data.size());
    intact.push_back(ok);
    cv.notify_all();
  });
  w.add_output("/sr", "shmem");
  auto route = w.output_names();
  ASSERT_EQ(route, std::vector<std::string>{"/sr"});
  const std::size_t sizes_sent[] = {921600, 20u << 20, 60, 921600};  // 20 MiB > the 8 MiB ring
  for (int k = 0; k < 4; ++k) {
    std::vector<std::uint8_t> pixels(sizes_sent[k]);
    for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<std::uint8_t>(i * 31 + k);
    Bottle img{Value(k), Value::blob(pixels.data(), pixels.size())};
    ASSERT_TRUE(w.write(img));
  }
  {
    std::unique_lock<std::mutex> lock(mutex);
    ASSERT_TRUE(cv.wait_for(lock, 10s, [&] { return sizes.size() == 4; }));
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(sizes[k], sizes_sent[k]);
      EXPECT_TRUE(intact[k]) << k;
    }
  }
  Bottle reply;
  ASSERT_TRUE(w.write(Bottle{Value("ping")}, reply));
  EXPECT_EQ(reply.to_text(), "got shmem");
  // Closing the writer ends the reader's input (the "q" goes through the ring).
  w.close();
  for (int i = 0; i < 100 && !r.input_names().empty(); ++i) std::this_thread::sleep_for(20ms);
  EXPECT_TRUE(r.input_names().empty());
}
