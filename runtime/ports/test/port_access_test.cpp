// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Who may control a port (docs/security.md), written as the attack: a peer that is not on the
// allow-list (127.0.0.2, while the list holds only 127.0.0.1) tries to connect the port
// elsewhere, drop its connections, set properties and thread scheduling; each is refused with a
// reply that says why, and nothing changes. Then a legitimate local client does the same and
// is served.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <thread>

#include "robogene/testing/connect_from.hpp"
#include "robogene/testing/wire_helpers.hpp"
#include "robogene/testing/port_test_util.hpp"
#include "robogene/access_policy.hpp"
#include "robogene/error.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

PortOptions only_127_0_0_1() {
  PortOptions o;
  o.access = AccessPolicy::parse("127.0.0.1");
  return o;
}

// One text_ack admin exchange from `source`, as `yarp connect` does it.
std::string admin_from(const std::string& source, const Port& p, const std::string& request,
                       const std::string& sender = "admin") {
  auto s = connect_from(source, p.contact().endpoint());
  send(s, "CONNACK " + sender + "\r\n");
  if (read_until(s, "\r\n") != "Welcome " + sender + "\r\n") return "(no welcome)";
  send(s, "a\r\n" + request + "\r\n");
  return read_until(s, "<ACK>\r\n");
}

// One text-mode command ("/port", "!port", "~port") from `source`; the port's answer.
std::string command_from(const std::string& source, const Port& p, const std::string& command) {
  auto s = connect_from(source, p.contact().endpoint());
  send(s, std::string("CONNACK telnet\r\n"));
  read_until(s, "\r\n");
  send(s, command + "\r\n");
  return read_until(s, "<ACK>\r\n");
}

const char kRefused[] = "is not on this process's allow-list (set ROBOGENE_ALLOW";

}  // namespace

TEST(PortAccess, AStrangerCannotConnectDisconnectOrConfigureButALocalClientCan) {
  PortTable t;
  Port w(only_127_0_0_1()), r(only_127_0_0_1()), elsewhere;
  open_local(w, "/w", t);
  open_local(r, "/r", t);
  open_local(elsewhere, "/elsewhere", t);
  w.add_output("/r");

  // The attack, from 127.0.0.2.
  std::string reply = admin_from("127.0.0.2", w, "[add] \"/elsewhere\"");
  EXPECT_NE(reply.find("-1 \"[add] refused: peer 127.0.0.2 " + std::string(kRefused)), std::string::npos) << reply;
  reply = admin_from("127.0.0.2", w, "[del] \"/r\"");
  EXPECT_NE(reply.find("[del] refused: peer 127.0.0.2"), std::string::npos) << reply;
  reply = admin_from("127.0.0.2", w, "[prop] [set] gain 3");
  EXPECT_NE(reply.find("[fail] \"[prop] refused: peer 127.0.0.2"), std::string::npos) << reply;
  reply = admin_from("127.0.0.2", w, "[prop] [set] \"/w\" (process ((priority 0) (policy 0)))");
  EXPECT_NE(reply.find("[fail] \"[prop] refused"), std::string::npos) << reply;
  reply = admin_from("127.0.0.2", w, "[prop] [set] \"/r\" (qos ((tos 184)))");
  EXPECT_NE(reply.find("[fail] \"[prop] refused"), std::string::npos) << reply;
  for (const char* command : {"/elsewhere", "!/r", "~/anyone"}) {
    reply = command_from("127.0.0.2", w, command);
    EXPECT_NE(reply.find(std::string("\"") + command + "\" refused: peer 127.0.0.2"), std::string::npos) << reply;
  }
  EXPECT_EQ(w.output_names(), std::vector<std::string>{"/r"});
  EXPECT_EQ(admin_from("127.0.0.2", w, "[prop] [get] gain"), "\r\n<ACK>\r\n");
  // Reading is open to everyone, as in YARP.
  EXPECT_EQ(admin_from("127.0.0.2", w, "[list] [out]"), "\"/r\"\r\n<ACK>\r\n");
  EXPECT_EQ(admin_from("127.0.0.2", w, "[ver]"), "[ver] 1 2 3\r\n<ACK>\r\n");

  // The legitimate client, from 127.0.0.1.
  EXPECT_EQ(admin_from("127.0.0.1", w, "[prop] [set] gain 3"), "[ok]\r\n<ACK>\r\n");
  EXPECT_EQ(admin_from("127.0.0.1", w, "[prop] [get] gain"), "3\r\n<ACK>\r\n");
  EXPECT_EQ(admin_from("127.0.0.1", w, "[add] \"/elsewhere\""),
            "0 \"Added connection from /w to /elsewhere\\r\\n\"\r\n<ACK>\r\n");
  EXPECT_EQ(admin_from("127.0.0.1", w, "[del] \"/r\""), "0 \"Removed connection from /w to /r\\r\\n\"\r\n<ACK>\r\n");
  EXPECT_EQ(w.output_names(), std::vector<std::string>{"/elsewhere"});
  // Data is still served to anyone: the port's owner decides what a message may do.
  std::thread writer([&] {
    auto s = connect_from("127.0.0.2", r.contact().endpoint());
    send(s, std::string("CONNACK /stranger\r\n"));
    read_until(s, "\r\n");
    send(s, std::string("d\r\n7 8\r\n"));
    read_until(s, "<ACK>\r\n");
  });
  Bottle b;
  EXPECT_TRUE(r.read(b, false, 5000ms));
  writer.join();
  EXPECT_EQ(b.to_text(), "7 8");
}

TEST(PortAccess, APeerMayDropAConnectionItIsTheOtherEndOf) {
  // A writer on another machine closing its connection (out_of_band_close sends [del] "/w" for
  // udp and mcast) is not a stranger to that connection, whatever the allow-list says.
  PortTable t;
  Port r(only_127_0_0_1());
  open_local(r, "/r", t);
  auto input = connect_from("127.0.0.2", r.contact().endpoint());
  send(input, std::string("CONNACK /w\r\n"));
  ASSERT_EQ(read_until(input, "\r\n"), "Welcome /w\r\n");
  ASSERT_TRUE(wait_until([&] { return r.input_names() == std::vector<std::string>{"/w"}; }));
  EXPECT_NE(admin_from("127.0.0.3", r, "[del] \"/w\"").find("[del] refused: peer 127.0.0.3"), std::string::npos);
  const auto names = r.input_names();  // "/w", and the admin connection until it is reaped
  EXPECT_NE(std::find(names.begin(), names.end(), "/w"), names.end());
  EXPECT_EQ(admin_from("127.0.0.2", r, "[del] \"/w\""), "0 \"Removing connection from /w to /r\\r\\n\"\r\n<ACK>\r\n");
  EXPECT_TRUE(wait_until([&] {
    const auto left = r.input_names();
    return std::find(left.begin(), left.end(), "/w") == left.end();
  }));
}

TEST(PortAccess, TheDefaultPolicyTrustsEveryAddressOfThisHostOnly) {
  Port p;  // no options: the environment's policy, "local" unless ROBOGENE_ALLOW says otherwise
  PortTable t;
  ::unsetenv("ROBOGENE_ALLOW");
  open_local(p, "/p", t);
  EXPECT_EQ(admin_from("127.0.0.2", p, "[prop] [set] gain 1"), "[ok]\r\n<ACK>\r\n");
  EXPECT_TRUE(is_local_address("127.0.0.1"));
  EXPECT_TRUE(is_local_address("127.1.2.3"));
  EXPECT_TRUE(is_local_address("::1"));
  EXPECT_TRUE(is_local_address("::ffff:127.0.0.1"));
  EXPECT_FALSE(is_local_address("192.0.2.7"));  // TEST-NET-1: never this host's
  EXPECT_FALSE(is_local_address("not an address"));
  const AccessPolicy local;
  EXPECT_FALSE(local.allows("192.0.2.7"));
  EXPECT_FALSE(local.http_writes());
  EXPECT_EQ(local.describe(), "local");
}

TEST(PortAccess, AllowListsParseAndBadOnesAreNamed) {
  const AccessPolicy p = AccessPolicy::parse("10.1.0.0/16, 192.0.2.7 local");
  EXPECT_EQ(p.describe(), "local 10.1.0.0/16 192.0.2.7/32");
  EXPECT_TRUE(p.allows("10.1.200.3"));
  EXPECT_TRUE(p.allows("::ffff:10.1.0.1"));
  EXPECT_FALSE(p.allows("10.2.0.1"));
  EXPECT_TRUE(p.allows("192.0.2.7"));
  EXPECT_FALSE(p.allows("192.0.2.8"));
  EXPECT_TRUE(AccessPolicy::parse("any").allows("203.0.113.9"));
  EXPECT_FALSE(AccessPolicy::parse("none").allows("127.0.0.1"));
  EXPECT_FALSE(AccessPolicy::parse("").allows("127.0.0.1"));
  EXPECT_TRUE(AccessPolicy::parse("0.0.0.0/0").allows("203.0.113.9"));
  try {
    AccessPolicy::parse("local,10.0.0.0/33", "ROBOGENE_ALLOW");
    FAIL() << "a prefix of 33 bits was taken";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "ROBOGENE_ALLOW: \"10.0.0.0/33\" has a prefix length that is not 0..32");
  }
  EXPECT_THROW(AccessPolicy::parse("banana"), Error);
  EXPECT_THROW(AccessPolicy::parse("10.0.0.0/"), Error);
  EXPECT_THROW(AccessPolicy::parse("10.0.0.0/8x"), Error);
  ::setenv("ROBOGENE_HTTP_WRITES", "yes", 1);
  EXPECT_THROW(AccessPolicy::from_environment(), Error);
  ::setenv("ROBOGENE_HTTP_WRITES", "1", 1);
  EXPECT_TRUE(AccessPolicy::from_environment().http_writes());
  ::unsetenv("ROBOGENE_HTTP_WRITES");
  // A port whose environment holds a bad list refuses to open, naming the variable.
  ::setenv("ROBOGENE_ALLOW", "10.0.0.300", 1);
  Port port;
  try {
    port.open_at("/p", {"127.0.0.1", 0});
    FAIL() << "opened with a bad ROBOGENE_ALLOW";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("ROBOGENE_ALLOW: \"10.0.0.300\""), std::string::npos) << e.what();
  }
  ::unsetenv("ROBOGENE_ALLOW");
}
