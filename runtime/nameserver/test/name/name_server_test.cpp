// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The name server on loopback, reached through each carrier: raw name_ser bytes as YARP's
// NameClient sends them (yarp-captures/yarp_name_cmds.flows.txt), the name_ser carrier from the
// registry, binary tcp with `bot`, text_ack admin.
#include "robogene/name/name_server.hpp"

#include <gtest/gtest.h>
#include <sys/socket.h>

#include <string>
#include <thread>

#include "robogene/carrier/registry.hpp"
#include "robogene/error.hpp"
#include "robogene/name/local_name_server.hpp"
#include "robogene/name/name_ser_carrier.hpp"
#include "robogene/net/tcp_listener.hpp"
#include "robogene/net/tcp_stream.hpp"

using namespace robogene;

namespace {

std::string exchange_raw(const net::Endpoint& at, const std::string& bytes) {
  net::TcpStream s = net::TcpStream::connect(at);
  s.set_read_timeout(net::Millis{5000});
  s.write_all(bytes.data(), bytes.size());
  ::shutdown(s.fd(), SHUT_WR);
  std::string out;
  char buf[4096];
  while (std::size_t n = s.read_some(buf, sizeof buf)) out.append(buf, n);
  return out;
}

std::unique_ptr<carrier::OutboundConnection> open(const net::Endpoint& at, const char* carrier_name) {
  carrier::ConnectContext ctx;
  ctx.sender_name = "/tester";
  ctx.target_name = "/root";
  return carrier::open_connection(at, carrier_name, ctx);
}

}  // namespace

TEST(NameServer, AnswersRawNameServerLinesAsCaptured) {
  name::LocalNameServer s;
  EXPECT_EQ(exchange_raw(s.contact(), "NAME_SERVER query /w\n"), "*** end of message\r\n");
  EXPECT_EQ(exchange_raw(s.contact(), "NAME_SERVER register /w\r\n"),
            "registration name /w ip 127.0.0.1 port " + std::to_string(s.contact().port + 2) +
                " type tcp\r\n*** end of message\r\n");
  EXPECT_EQ(exchange_raw(s.contact(), "NAME_SERVER announce /w\n"), "[ok]\r\n");
  EXPECT_EQ(exchange_raw(s.contact(), "NAME_SERVER unregister /w\n"), "*** end of message\r\n");
}

TEST(NameServer, NameSerCarrierFromTheRegistryBothWays) {
  name::LocalNameServer s;  // adds name_ser to the global registry
  auto c = carrier::CarrierRegistry::global().find("name_ser");
  ASSERT_TRUE(c);
  carrier::Header h = c->header();
  EXPECT_EQ(std::string(h.begin(), h.end()), "NAME_SER");
  auto conn = open(s.contact(), "name_ser");
  Bottle request = Bottle::from_text("register /bar tcp 127.0.0.1 12345");
  Bottle reply;
  carrier::OutboundMessage m;
  m.key = 'd';
  m.bottle = &request;
  conn->send(m, &reply);
  ASSERT_EQ(reply.size(), 1u);
  EXPECT_EQ(reply[0].as_string(), "registration name /bar ip 127.0.0.1 port 12345 type tcp");
  EXPECT_THROW(conn->send(m, &reply), Error) << "name_ser carries one request per connection";
}

TEST(NameServer, BinaryTcpBotRequestGetsABottle) {
  name::LocalNameServer s;
  auto conn = open(s.contact(), "tcp");
  Bottle request = Bottle::from_text("bot query /root");
  Bottle reply;
  carrier::OutboundMessage m;
  m.key = 'd';
  m.bottle = &request;
  conn->send(m, &reply);
  EXPECT_EQ(reply.to_text(), "port (name \"/root\") (ip \"127.0.0.1\") (port_number " + std::to_string(s.contact().port) +
                                 ") (carrier tcp)");
  conn->send(m, &reply);  // the connection stays usable
  EXPECT_EQ(reply.size(), 5u);
  conn->close();
}

TEST(NameServer, TextAckAdminRequests) {
  name::LocalNameServer s;
  auto conn = open(s.contact(), "text_ack");
  Bottle ver{Value::vocab("ver")}, reply;
  carrier::OutboundMessage m;
  m.key = 'a';
  m.bottle = &ver;
  conn->send(m, &reply);
  EXPECT_EQ(reply.to_text(), "[ver] 1 2 3");
  Bottle list_in = Bottle::from_text("[list] [in]");
  m.bottle = &list_in;
  conn->send(m, &reply);
  EXPECT_EQ(reply.to_text(), "\"/tester\"") << "the admin connection itself is an input of /root";
  conn->close();
}

TEST(NameServer, UnknownCarrierIsToldAndClosed) {
  name::LocalNameServer s;
  // (Not an HTTP request: /root answers those, as yarpserver does, through the http carrier.)
  std::string reply = exchange_raw(s.contact(), "SSH-2.0-OpenSSH_9.2\r\n");
  EXPECT_NE(reply.find("CONNECT foo"), std::string::npos) << reply;
  EXPECT_EQ(exchange_raw(s.contact(), "NAME_SERVER query /root\n").rfind("registration name /root", 0), 0u);
}
