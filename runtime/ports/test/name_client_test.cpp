// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// NameClient against a raw-socket stand-in for yarpserver that records the exact request
// bytes (they must be what YARP 3 clients send, reference 4.1) and answers with captured replies.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <mutex>
#include <thread>

#include "robogene/testing/wire_helpers.hpp"
#include "robogene/error.hpp"
#include "robogene/name_client.hpp"
#include "robogene/name_config.hpp"
#include "robogene/port.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

// Serves `count` connections; each request is answered by `answer(request)`.
class FakeNameServer {
 public:
  template <typename Answer>
  FakeNameServer(int count, Answer answer) {
    thread_ = std::thread([this, count, answer] {
      for (int i = 0; i < count; ++i) {
        auto s = listener_.accept(5000ms);
        if (!s) return;
        std::string req = read_until(*s, "\n");
        {
          std::lock_guard<std::mutex> lock(mutex_);
          requests_.push_back(req);
        }
        send(*s, answer(req));
      }
    });
  }
  ~FakeNameServer() {
    listener_.interrupt();
    thread_.join();
  }
  net::Endpoint at() const { return listener_.local(); }
  std::vector<std::string> requests() {
    std::lock_guard<std::mutex> lock(mutex_);
    return requests_;
  }

 private:
  net::TcpListener listener_ = net::TcpListener::listen({"127.0.0.1", 0});
  std::thread thread_;
  std::mutex mutex_;
  std::vector<std::string> requests_;
};

const std::string kEnd = "*** end of message\r\n";

}  // namespace

TEST(NameClient, QuerySendsYarpBytesAndParsesTheCapturedReply) {
  FakeNameServer srv(2, [](const std::string& req) {
    if (req == "NAME_SERVER query /motors/rpc:i\n") {
      return "registration name /motors/rpc:i ip 127.0.0.1 port 10004 type tcp\r\n" + kEnd;
    }
    return kEnd;
  });
  NameClient nc(srv.at());
  auto c = nc.query("/motors/rpc:i");
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->host, "127.0.0.1");
  EXPECT_EQ(c->port, 10004);
  EXPECT_EQ(c->carrier, "tcp");
  EXPECT_FALSE(nc.query("/w").has_value());
  EXPECT_EQ(srv.requests(), (std::vector<std::string>{"NAME_SERVER query /motors/rpc:i\n",
                                                      "NAME_SERVER query /w\n"}));
}

TEST(NameClient, RegisterExplicitAndUnregisterBytes) {
  FakeNameServer srv(3, [](const std::string& req) {
    if (req.rfind("NAME_SERVER register /bar", 0) == 0) {
      return "registration name /bar ip 127.0.0.1 port 12345 type tcp\r\n" + kEnd;
    }
    return kEnd;
  });
  NameClient nc(srv.at());
  Contact c = nc.register_name("/bar", "tcp", "127.0.0.1", 12345);
  EXPECT_EQ(c.port, 12345);
  nc.unregister("/bar");
  EXPECT_THROW(nc.register_name("/refused"), Error);
  auto r = srv.requests();
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0], "NAME_SERVER register /bar tcp 127.0.0.1 12345\r\n");
  EXPECT_EQ(r[1], "NAME_SERVER unregister /bar\n");
  EXPECT_EQ(r[2], "NAME_SERVER register /refused\r\n");
}

TEST(NameClient, UnreachableServerIsNamedInTheError) {
  auto l = net::TcpListener::listen({"127.0.0.1", 0});
  net::Endpoint gone = l.local();
  l.close();
  NameClient nc(gone);
  try {
    nc.query("/x");
    FAIL();
  } catch (const NetworkError& e) {
    EXPECT_NE(std::string(e.what()).find(gone.to_string()), std::string::npos) << e.what();
  }
}

TEST(NameClient, PortOpenRegistersListensWhereToldAndUnregistersOnClose) {
  // A free number for the server to hand out.
  int port;
  {
    auto probe = net::TcpListener::listen({"127.0.0.1", 0});
    port = probe.local().port;
  }
  FakeNameServer srv(5, [port](const std::string& req) {
    if (req == "NAME_SERVER register /w\r\n") {
      return "registration name /w ip 127.0.0.1 port " + std::to_string(port) + " type tcp\r\n" + kEnd;
    }
    if (req.rfind("NAME_SERVER set /w process ", 0) == 0) {
      return "port /w property process = 1\r\n" + kEnd;
    }
    return kEnd;
  });
  {
    Port w;
    w.open("/w", NameClient(srv.at()));
    EXPECT_EQ(w.contact().port, port);
    auto s = net::TcpStream::connect({"127.0.0.1", port});  // really listening there
  }
  auto r = srv.requests();
  ASSERT_EQ(r.size(), 5u);
  EXPECT_EQ(r[0], "NAME_SERVER register /w\r\n");
  EXPECT_EQ(r[1].rfind("NAME_SERVER set /w offers tcp fast_tcp text text_ack udp", 0), 0u) << r[1];
  EXPECT_EQ(r[2].rfind("NAME_SERVER set /w accepts tcp", 0), 0u) << r[2];
  EXPECT_EQ(r[3].rfind("NAME_SERVER set /w process ", 0), 0u) << r[3];
  EXPECT_EQ(r[4], "NAME_SERVER unregister /w\n");
}

TEST(NameConfig, ParsesBothFileShapesAndReportsLines) {
  auto a = NameConfig::parse("127.0.0.1 10000 yarp\n", "yarp.conf");
  EXPECT_EQ(a.server.to_string(), "127.0.0.1:10000");
  auto b = NameConfig::parse("[name]\nhost 10.0.0.2\nport 10042\nmode yarp\n", "g.conf");
  EXPECT_EQ(b.server.to_string(), "10.0.0.2:10042");
  try {
    NameConfig::parse("\n127.0.0.1 tenthousand\n", "bad.conf");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.conf:2"), std::string::npos) << e.what();
  }
  EXPECT_EQ(NameConfig::file_name_for("/root"), "yarp.conf");
  EXPECT_EQ(NameConfig::file_name_for("/myns"), "_myns.conf");
  EXPECT_EQ(NameConfig::parse_server("localhost:10001").port, 10001);
  EXPECT_THROW(NameConfig::parse_server("localhost"), Error);
  EXPECT_THROW(NameConfig::parse_server("h:70000"), Error);
}

TEST(NameConfig, FindsTheFileTheYarp3Way) {
  std::string dir = ::testing::TempDir() + "/robogene-nameconf";
  std::string cmd = "mkdir -p " + dir + "/yarp";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  std::ofstream(dir + "/yarp/yarp.conf") << "127.0.0.1 10111 yarp\n";
  std::ofstream(dir + "/yarp/_myns.conf") << "127.0.0.1 10222 yarp\n";
  ::unsetenv("YARP_CONFIG_HOME");
  ::unsetenv("YARP_NAMESPACE");
  ::setenv("XDG_CONFIG_HOME", dir.c_str(), 1);
  EXPECT_EQ(NameConfig::load().server.port, 10111);
  ::setenv("YARP_NAMESPACE", "/myns", 1);
  EXPECT_EQ(NameConfig::load().server.port, 10222);
  ::setenv("YARP_CONFIG_HOME", (dir + "/yarp").c_str(), 1);
  ::unsetenv("YARP_NAMESPACE");
  EXPECT_EQ(NameConfig::load().server.port, 10111);
  ::setenv("YARP_CONFIG_HOME", (dir + "/nowhere").c_str(), 1);
  try {
    NameConfig::load();
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(dir + "/nowhere/yarp.conf"), std::string::npos) << e.what();
  }
  ::unsetenv("YARP_CONFIG_HOME");
  ::unsetenv("XDG_CONFIG_HOME");
}
