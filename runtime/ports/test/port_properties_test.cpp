// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The admin message [prop]: user-defined port properties, per-connection QoS (the IP_TOS byte of
// the connection's socket) and scheduling, and the port's own process information.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "robogene/testing/wire_helpers.hpp"
#include "robogene/testing/port_test_util.hpp"

using namespace robogene;
using namespace robogene::test;

namespace {

// The reply line of one admin exchange, without its "\r\n<ACK>\r\n".
std::string admin(const Port& p, const std::string& request) {
  std::string reply = admin_text(p, request);
  const std::string end = "\r\n<ACK>\r\n";
  return reply.size() >= end.size() ? reply.substr(0, reply.size() - end.size()) : reply;
}

struct PortPropertiesConnected : ::testing::Test {
  PortTable t;
  Port w, r;
  void SetUp() override {
    open_local(w, "/w", t);
    open_local(r, "/r", t);
    w.add_output("/r");
    ASSERT_TRUE(wait_until([&] { return admin(r, "[list] [in]").find("\"/w\"") != std::string::npos; }));
  }
};

}  // namespace

TEST(PortProperties, UserPropertiesAreSetReplacedAndListed) {
  PortTable t;
  Port p;
  open_local(p, "/p", t);
  EXPECT_EQ(admin(p, "[prop] [get]"), "");
  EXPECT_EQ(admin(p, "[prop] [get] gain"), "");
  EXPECT_EQ(admin(p, "[prop] [set] gain 3"), "[ok]");
  EXPECT_EQ(admin(p, "[prop] [set] label \"left eye\""), "[ok]");
  EXPECT_EQ(admin(p, "[prop] [set] gain 4.5"), "[ok]");
  EXPECT_EQ(admin(p, "[prop] [get] gain"), "4.5");
  EXPECT_EQ(admin(p, "[prop] [get]"), "(label \"left eye\") (gain 4.5)");
}

TEST_F(PortPropertiesConnected, OutputQosIsTheSocketsTosByte) {
  EXPECT_EQ(admin(w, "[prop] [get] /r"), "(sched ((policy -1) (priority -1) (tid -1))) (qos ((tos 0)))");
  EXPECT_EQ(admin(w, "[prop] [set] /r (qos ((dscp AF41)))"), "[ok]");
  EXPECT_EQ(admin(w, "[prop] [get] /r"), "(sched ((policy -1) (priority -1) (tid -1))) (qos ((tos 136)))");
  EXPECT_EQ(admin(w, "[prop] [set] /r (qos ((priority HIGH)))"), "[ok]");
  EXPECT_NE(admin(w, "[prop] [get] /r").find("(tos 144)"), std::string::npos);
  EXPECT_EQ(admin(w, "[prop] [set] /r (qos ((tos 32)))"), "[ok]");
  EXPECT_NE(admin(w, "[prop] [get] /r").find("(tos 32)"), std::string::npos);
  // Data still flows after the change.
  std::atomic<bool> got{false};
  r.set_reader([&](const Bottle& b, const MessageInfo&, Bottle*) { got = b == Bottle{Value(7)}; });
  w.write(Bottle{Value(7)});
  EXPECT_TRUE(wait_until([&] { return got.load(); }));
}

TEST_F(PortPropertiesConnected, InputSchedulingNamesTheConnectionsThread) {
  Bottle reply = Bottle::from_text(admin(r, "[prop] [get] /w"));
  const Bottle* sched = reply.find_group("sched");
  ASSERT_NE(sched, nullptr) << reply.to_text();
  const Bottle& fields = sched->get(1).as_list();
  const int tid = fields.find("tid").as_int32();
  EXPECT_TRUE(std::filesystem::exists("/proc/self/task/" + std::to_string(tid))) << tid;
  EXPECT_EQ(fields.find("policy").as_int32(), 0);  // SCHED_OTHER
  EXPECT_EQ(admin(r, "[prop] [set] /w (sched ((priority 0) (policy 0)))"), "[ok]");
  // An output has no thread of its own to schedule.
  EXPECT_EQ(admin(w, "[prop] [set] /r (sched ((priority 0) (policy 0)))"), "[fail]");
}

TEST_F(PortPropertiesConnected, BadRequestsAreNamed) {
  EXPECT_EQ(admin(w, "[prop] [get] /ghost"), "[fail] \"cannot find any connection to/from /ghost\"");
  EXPECT_EQ(admin(w, "[prop] [set] /ghost (qos ((tos 4)))"), "[fail] \"cannot find any connection to/from /ghost\"");
  EXPECT_NE(admin(w, "[prop] [set] /r (qos ((tos 999)))").find("[fail] \"(qos ...) needs"), std::string::npos);
  EXPECT_NE(admin(w, "[prop] [set] /r (qos ((dscp XX99)))").find("[fail]"), std::string::npos);
  EXPECT_NE(admin(w, "[prop] [set] /r").find("needs (qos"), std::string::npos);
  EXPECT_NE(admin(w, "[prop] [frob]").find("property action not known"), std::string::npos);
  EXPECT_NE(admin(w, "[prop] [set] /r (process ((priority 0)))").find("this port's own name"), std::string::npos);
}

TEST_F(PortPropertiesConnected, OwnNameDescribesThreadProcessAndPlatform) {
  Bottle reply = Bottle::from_text(admin(w, "[prop] [get] /w"));
  ASSERT_NE(reply.find_group("sched"), nullptr) << reply.to_text();
  const Bottle* process = reply.find_group("process");
  ASSERT_NE(process, nullptr) << reply.to_text();
  EXPECT_EQ(process->get(1).as_list().find("pid").as_int32(), static_cast<int>(getpid()));
  const Bottle* platform = reply.find_group("platform");
  ASSERT_NE(platform, nullptr);
  EXPECT_EQ(platform->get(1).as_list().find("os").as_string(), "Linux");
  EXPECT_EQ(platform->get(1).as_list().find("hostname").as_string(), "127.0.0.1");
  // /w has only had an output added; /r has not been read from yet.
  EXPECT_EQ(reply.find_group("port")->to_text(), "port ((is_input 0) (is_output 1) (is_rpc 0) (type \"\"))");
  r.set_reader([](const Bottle&, const MessageInfo&, Bottle*) {});
  EXPECT_NE(admin(r, "[prop] [get] /r").find("(port ((is_input 1) (is_output 0) (is_rpc 0)"), std::string::npos);
}
