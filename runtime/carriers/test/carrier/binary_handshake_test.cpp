// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The binary handshake helper every binary carrier uses (tcp, fast_tcp, udp, mcast, shmem): the
// bytes of the initiator's hello as YARP's `yarp write /w` sends them, the acceptor's answer, and
// the errors for a peer that answers something else or announces a bad name.
#include "robogene/carrier/binary_handshake.hpp"

#include <gtest/gtest.h>

#include <future>
#include <memory>

#include "robogene/error.hpp"
#include "robogene/net/tcp_listener.hpp"
#include "robogene/testing/wire_helpers.hpp"

using namespace robogene;
using namespace robogene::carrier;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

// Two ends of one loopback connection: `ours` wrapped as a carrier Link, `theirs` raw.
struct Pair {
  std::unique_ptr<Link> ours;
  net::TcpStream theirs;
};

Pair connected() {
  auto l = net::TcpListener::listen({"127.0.0.1", 0});
  auto theirs = std::async(std::launch::async, [&] { return l.accept(5000ms); });
  Pair p{std::make_unique<Link>(net::TcpStream::connect(l.local())), {}};
  auto accepted = theirs.get();
  if (!accepted) throw NetworkError("loopback accept timed out");
  p.theirs = std::move(*accepted);
  p.theirs.set_read_timeout(5000ms);
  p.ours->stream.set_read_timeout(5000ms);
  return p;
}

}  // namespace

TEST(BinaryHandshake, HelloIsHeaderThenLengthNameNulAsYarpWriteSendsIt) {
  // `yarp write /w` to a tcp reader (yarp-captures): YA e4 1e 00 00 RP, int32 3, "/w", NUL.
  EXPECT_EQ(binary_hello(make_yarp_number(kTcpSpecifier), "/w"),
            hex("59 41 e4 1e 00 00 52 50 03 00 00 00 2f 77 00"));
  // mcast adds its group after the name: 224.1.1.3, port 10005 big-endian.
  EXPECT_EQ(binary_hello(make_yarp_number(kMcastSpecifier), "/w", {224, 1, 1, 3, 0x27, 0x15}),
            hex("59 41 62 1e 00 00 52 50 03 00 00 00 2f 77 00 e0 01 01 03 27 15"));
}

TEST(BinaryHandshake, InitiatorSendsHelloAndReadsTheAnswerNumber) {
  Pair p = connected();
  send_binary_hello(*p.ours, make_yarp_number(kFastTcpSpecifier), "/sender");
  EXPECT_EQ(read_n(p.theirs, 8 + 4 + 8), hex("59 41 64 1e 00 00 52 50 08 00 00 00 2f 73 65 6e 64 65 72 00"));
  send(p.theirs, hex("59 41 13 27 00 00 52 50"));  // YA <10003> RP
  EXPECT_EQ(read_binary_answer(*p.ours, "handshake with /r", "YA <port> RP"), 10003);
}

TEST(BinaryHandshake, AnAnswerThatIsNoYarpNumberNamesWhereWhatWasExpectedAndTheBytes) {
  Pair p = connected();
  send(p.theirs, std::string("Protocol"));
  try {
    read_binary_answer(*p.ours, "udp handshake with /r (somewhere)", "YA <udp port> RP");
    FAIL() << "accepted a non-YARP answer";
  } catch (const NetworkError& e) {
    EXPECT_STREQ(e.what(), "udp handshake with /r (somewhere): expected YA <udp port> RP, got "
                           "50 72 6f 74 6f 63 6f 6c");
  }
}

TEST(BinaryHandshake, AcceptorReadsTheNameDropsQualifiersAndAnswers) {
  Pair p = connected();
  // The 8 header bytes were read by the carrier registry; the name follows: "/w (log.in 1)".
  send(p.theirs, hex("0e 00 00 00 2f 77 20 28 6c 6f 67 2e 69 6e 20 31 29 00"));
  EXPECT_EQ(read_binary_sender_name(*p.ours, 1000), "/w");
  send_binary_answer(*p.ours, 10002);
  EXPECT_EQ(read_n(p.theirs, 8), hex("59 41 12 27 00 00 52 50"));
}

TEST(BinaryHandshake, ANameLengthOutOfRangeIsAParseErrorAtOffsetEight) {
  for (const char* length : {"00 00 00 00", "e9 03 00 00", "ff ff ff ff"}) {  // 0, 1001, -1
    Pair p = connected();
    send(p.theirs, hex(length));
    try {
      read_binary_sender_name(*p.ours, 1000);
      FAIL() << "accepted sender name length " << length;
    } catch (const ParseError& e) {
      EXPECT_EQ(e.position(), 8u);
      EXPECT_NE(std::string(e.what()).find("at byte offset 8 is outside 1..1000"), std::string::npos) << e.what();
    }
  }
}
