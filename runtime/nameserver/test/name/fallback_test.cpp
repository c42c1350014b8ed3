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

#include "robogene/carrier/crc32.hpp"
#include "robogene/net/mcast_socket.hpp"
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

// The attack: anyone on the network can send a datagram to the group, with any source address.
// Before, `NAME_SERVER register` / `unregister` from one changed the registry; now only requests
// that read are served, and the others get an error that says why.
TEST_F(Fallback, WritesFromADatagramAreRefusedAndReadsAreStillAnswered) {
  name::FallbackResponder responder(service, "127.0.0.1", group);
  auto group_listener = net::McastSocket::join(group, "127.0.0.1");
  auto sender = net::UdpSocket::bind({"127.0.0.1", 0});
  for (const std::string text : {"NAME_SERVER register /spoof tcp 127.0.0.1 9999\n",
                                 "NAME_SERVER unregister /root\n", "NAME_SERVER bot set /root owner me\n"}) {
    std::string datagram(8, '\0');
    const std::uint32_t crc = carrier::crc32(text.data(), text.size());
    for (int i = 0; i < 4; ++i) datagram[i] = static_cast<char>(crc >> (8 * i));
    datagram += text;
    sender.send_to(group, datagram.data(), datagram.size());
    std::string answer;
    std::vector<char> buf(65536);
    for (int i = 0; i < 20 && answer.find("refused") == std::string::npos; ++i) {
      auto n = group_listener.receive(buf.data(), buf.size(), net::Millis(200));
      if (n && *n > 8) answer.assign(buf.data() + 8, *n - 8);
    }
    EXPECT_NE(answer.find("*** error: refused \"" + text.substr(0, text.size() - 1) + "\": the multicast fallback "
                          "answers only requests that read"),
              std::string::npos)
        << answer;
  }
  EXPECT_FALSE(db.find("/spoof").has_value());
  EXPECT_TRUE(db.find("/root").has_value());
  EXPECT_TRUE(db.get_property("/root", "owner").empty());
  // The legitimate use still works.
  auto found = name::detect_name_server("127.0.0.1", "/root", net::Millis(1500), group);
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->port, 10321);
}

TEST(NameServiceAccess, OnlyReadingRequestsCountAsReadOnly) {
  for (const char* text : {"query /r", "NAME_SERVER query /r", "bot list", "NAME_SERVER bot get /r x", "help",
                           "check /r x y", "route /a /b", "runners", ""}) {
    EXPECT_TRUE(name::NameService::is_read_only(Bottle::from_text(text))) << text;
  }
  for (const char* text : {"register /r", "NAME_SERVER unregister /r", "bot set /r x y", "announce /r", "gc",
                           "NAME_SERVER bot register /r", "nonsense"}) {
    EXPECT_FALSE(name::NameService::is_read_only(Bottle::from_text(text))) << text;
  }
}
