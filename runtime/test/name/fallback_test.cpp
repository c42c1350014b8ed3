// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The multicast fallback: a responder answers `NAME_SERVER query /root` on its group, a detecting
// client finds the server's address, and datagrams that are not requests (bad CRC, too short,
// another server's reply, another namespace) are ignored without stopping the responder.
#include "robogene/name/fallback.hpp"

#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include "robogene/name/registry.hpp"
#include "robogene/net/udp_socket.hpp"

using namespace robogene;

namespace {

// A group port nobody else uses: the number of a UDP port the kernel just handed out.
int private_group_port() {
  auto s = net::UdpSocket::bind({"127.0.0.1", 0});
  return s.local().port;
}

struct Fallback : ::testing::Test {
  name::Registry db{":memory:"};
  name::NameServiceConfig config = [] {
    name::NameServiceConfig c;
    c.host = "127.0.0.1";
    c.port = 10321;
    return c;
  }();
  name::NameService service{db, config, nullptr};
  net::Endpoint group{"224.2.1.1", private_group_port()};
};

}  // namespace

TEST_F(Fallback, DetectFindsTheServerThroughTheGroup) {
  name::FallbackResponder responder(service, "127.0.0.1", group);
  auto found = name::detect_name_server("127.0.0.1", "/root", net::Millis(1500), group);
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->to_string(), "127.0.0.1:10321");
  // Only /root is registered: another namespace gets no answer worth taking.
  EXPECT_FALSE(name::detect_name_server("127.0.0.1", "/elsewhere", net::Millis(600), group).has_value());
}

TEST_F(Fallback, GarbageDatagramsAreIgnoredAndTheResponderKeepsAnswering) {
  name::FallbackResponder responder(service, "127.0.0.1", group);
  auto sender = net::UdpSocket::bind({"127.0.0.1", 0});
  const std::string bad_crc = std::string("\x01\x02\x03\x04\0\0\0\0", 8) + "NAME_SERVER query /root\n";
  sender.send_to(group, bad_crc.data(), bad_crc.size());
  sender.send_to(group, "abc", 3);
  auto found = name::detect_name_server("127.0.0.1", "/root", net::Millis(1500), group);
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->port, 10321);
}

TEST_F(Fallback, NoServerMeansNoAnswerWithinTheTimeout) {
  EXPECT_FALSE(name::detect_name_server("127.0.0.1", "/root", net::Millis(300), group).has_value());
}
