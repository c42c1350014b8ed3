// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The telnet protocol of paper section 4.4 and reference section 3.5.
#include <gtest/gtest.h>

#include <thread>

#include "robogene/testing/wire_helpers.hpp"
#include "robogene/testing/port_test_util.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {
net::TcpStream telnet(const Port& p, const std::string& hello = "CONNECT foo\r\n") {
  auto s = net::TcpStream::connect({"127.0.0.1", p.contact().port});
  send(s, hello);
  return s;
}
}  // namespace

TEST(PortText, WelcomeDataAndReplyAsInThePaper) {
  Port motors;
  motors.open_at("/motors", {"127.0.0.1", 0});
  motors.set_reader([](const Bottle& b, const MessageInfo& info, Bottle* reply) {
    EXPECT_EQ(info.from, "foo");
    EXPECT_EQ(info.carrier, "text");
    if (reply && b.get(0).as_vocab() == vocab("get")) {
      *reply = Bottle::from_text("[is] [axes] 2 [ok]");
    } else if (reply) {
      *reply = Bottle::from_text("[ok]");
    }
  });
  auto s = telnet(motors);
  EXPECT_EQ(read_until(s, "\r\n"), "Welcome foo\r\n");
  send(s, std::string("d\n[get] [axes]\n"));
  EXPECT_EQ(read_until(s, "\r\n"), "[is] [axes] 2 [ok]\r\n");
  send(s, std::string("d\r\n[set] [pos] 0 100.0\r\n"));
  EXPECT_EQ(read_until(s, "\r\n"), "[ok]\r\n");
}

TEST(PortText, TextAckAddsAckAndMultiLineBottlesAreJoined) {
  Port p;
  p.open_at("/p", {"127.0.0.1", 0});
  Bottle seen;
  p.set_reader([&](const Bottle& b, const MessageInfo&, Bottle* reply) {
    seen = b;
    if (reply) *reply = Bottle{Value(static_cast<std::int32_t>(b.size()))};
  });
  auto s = telnet(p, "CONNACK tester\r\n");
  EXPECT_EQ(read_until(s, "\r\n"), "Welcome tester\r\n");
  send(s, std::string("d\n(hello\nworld) 42 \\\n3.5 \"a string\" [vocb]\n"));
  EXPECT_EQ(read_until(s, "<ACK>\r\n"), "5\r\n<ACK>\r\n");
  EXPECT_EQ(seen.to_text(), "(hello world) 42 3.5 \"a string\" [vocb]");
  send(s, std::string("do\n1 2\n"));
  EXPECT_EQ(read_until(s, "<ACK>\r\n"), "<ACK>\r\n");
}

TEST(PortText, DescribeHelpAndUnknownCommand) {
  Port p;
  p.open_at("/demo", {"127.0.0.1", 0});
  auto s = telnet(p, "CONNACK foo\r\n");
  read_until(s, "\r\n");
  send(s, std::string("*\n"));
  std::string d = read_until(s, "<ACK>\r\n");
  EXPECT_EQ(d, "This is /demo at tcp://127.0.0.1:" + std::to_string(p.contact().port) +
                   "/\r\nThere are no outgoing connections\r\nThere is an input connection from "
                   "foo to /demo using text_ack\r\n<ACK>\r\n");
  send(s, std::string("?\n"));
  std::string help = read_until(s, "<ACK>\r\n");
  for (const char* cmd : {"\r\n*", "\r\nd ", "\r\ndo", "\r\nq", "\r\nr", "\r\n/port", "\r\n!/port",
                          "\r\n~/port", "\r\na ", "\r\n?"}) {
    EXPECT_NE(help.find(cmd), std::string::npos) << cmd << " missing in " << help;
  }
  send(s, std::string("xyz\n"));
  EXPECT_EQ(read_until(s, "<ACK>\r\n").rfind("Port command not understood.\r\n", 0), 0u);
}

TEST(PortText, SlashCommandsAddAndRemoveOutputs) {
  PortTable t;
  Port w, r;
  open_local(w, "/w", t);
  open_local(r, "/r", t);
  auto s = telnet(w, "CONNACK foo\r\n");
  read_until(s, "\r\n");
  send(s, std::string("/r\n"));
  EXPECT_EQ(read_until(s, "<ACK>\r\n"), "Added connection from /w to /r\r\n<ACK>\r\n");
  EXPECT_EQ(w.output_names(), std::vector<std::string>{"/r"});
  send(s, std::string("!/r\n"));
  EXPECT_EQ(read_until(s, "<ACK>\r\n"), "Removed connection from /w to /r\r\n<ACK>\r\n");
  send(s, std::string("~/nobody\n"));
  EXPECT_EQ(read_until(s, "<ACK>\r\n"), "Could not find an incoming connection from /nobody\r\n<ACK>\r\n");
}

TEST(PortText, ReverseTurnsATelnetSessionIntoAReader) {
  Port state;
  state.open_at("/motors/state:o", {"127.0.0.1", 0});
  auto s = telnet(state);
  read_until(s, "\r\n");
  send(s, std::string("r\n"));
  for (int i = 0; i < 100 && state.output_names().empty(); ++i) std::this_thread::sleep_for(10ms);
  ASSERT_EQ(state.output_names(), std::vector<std::string>{"foo"});
  ASSERT_TRUE(state.write(Bottle{100.0, 0.0}));
  ASSERT_TRUE(state.write(Bottle{100.0, 0.0}));
  EXPECT_EQ(read_until(s, "0.0\r\ndo\r\n100.0 0.0\r\n"), "do\r\n100.0 0.0\r\ndo\r\n100.0 0.0\r\n");
}

TEST(PortText, BinaryReverseStreamsIndexedMessagesThatTheReaderAcks) {
  Port state;
  state.open_at("/motors/state:o", {"127.0.0.1", 0});
  auto s = net::TcpStream::connect({"127.0.0.1", state.contact().port});
  send(s, hex("59 41 e4 1e 00 00 52 50 06 00 00 00 2f 73 6e 69 66 00"));  // "/snif"
  read_n(s, 8);
  send(s, hex("59 41 0a 00 00 00 52 50 01 01 ff ff ff ff ff ff ff ff 08 00 00 00 00 00 00 00"
              "00 00 00 00 7e 72 00 01"));
  EXPECT_EQ(read_n(s, 8), hex("59 41 00 00 00 00 52 50"));
  for (int i = 0; i < 100 && state.output_names().empty(); ++i) std::this_thread::sleep_for(10ms);
  std::thread writer([&] { EXPECT_TRUE(state.write(Bottle{Value(5)})); });
  auto msg = read_n(s, 8 + 10 + 12 + 8 + 12);
  send(s, hex("59 41 00 00 00 00 52 50"));
  writer.join();
  EXPECT_EQ(std::vector<std::uint8_t>(msg.end() - 20, msg.end()),
            hex("00 00 00 00 7e 44 00 01 01 01 00 00 01 00 00 00 05 00 00 00"));
}
