// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The in-process name server: a free port, /root registered where it really listens, the
// registrations kept in the file given, stale ones swept with the real probe, the port given back
// on destruction, and a clear error when the address is taken.
#include "robogene/name/local_name_server.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "robogene/error.hpp"
#include "robogene/log.hpp"
#include "robogene/net/tcp_listener.hpp"
#include "robogene/net/tcp_stream.hpp"

using namespace robogene;
using namespace std::chrono_literals;

TEST(LocalNameServer, ServesOnAFreePortAndRegistersRootThere) {
  name::LocalNameServer ns;
  ASSERT_GT(ns.contact().port, 0);
  EXPECT_EQ(ns.contact().host, "127.0.0.1");
  EXPECT_EQ(ns.address(), "127.0.0.1:" + std::to_string(ns.contact().port));
  auto root = ns.client().query("/root");
  ASSERT_TRUE(root.has_value());
  EXPECT_EQ(root->port, ns.contact().port);
  Contact w = ns.client().register_name("/w");
  EXPECT_EQ(ns.client().query("/w")->port, w.port);
}

TEST(LocalNameServer, TwoRunAtOnceOnDifferentPorts) {
  name::LocalNameServer a, b;
  EXPECT_NE(a.contact().port, b.contact().port);
  a.client().register_name("/only_in_a");
  EXPECT_FALSE(b.client().query("/only_in_a").has_value());
}

TEST(LocalNameServer, GivesItsPortBackWhenDestroyed) {
  net::Endpoint was;
  {
    name::LocalNameServer ns;
    was = ns.contact();
  }
  EXPECT_THROW(net::TcpStream::connect(was, net::Millis{1000}), NetworkError);
  // The same port can serve again at once.
  name::LocalNameServerOptions o;
  o.at = was;
  name::LocalNameServer again(o);
  EXPECT_EQ(again.contact(), was);
  EXPECT_TRUE(again.client().query("/root").has_value());
}

TEST(LocalNameServer, KeepsRegistrationsInTheDatabaseFileGiven) {
  const std::string db = ::testing::TempDir() + "/robogene-local-ns-" + std::to_string(::getpid()) + ".db";
  std::remove(db.c_str());
  name::LocalNameServerOptions o;
  o.db = db;
  {
    name::LocalNameServer first(o);
    first.client().register_name("/kept", "tcp", "127.0.0.1", 12345);
  }
  name::LocalNameServer second(o);
  auto kept = second.client().query("/kept");
  ASSERT_TRUE(kept.has_value());
  EXPECT_EQ(kept->port, 12345);
  std::remove(db.c_str());
}

TEST(LocalNameServer, SweepsEntriesWhosePortsAreGoneAndSaysWhich) {
  log::set_level(log::Level::Error);
  // A port number nobody listens on: bound, then closed.
  int dead_port = 0;
  {
    auto l = net::TcpListener::listen({"127.0.0.1", 0});
    dead_port = l.local().port;
  }
  std::mutex mutex;
  std::vector<std::string> dropped;
  name::LocalNameServerOptions o;
  o.probe_liveness = true;
  o.service.stale_grace_seconds = 0;
  o.service.recheck_seconds = 0;
  o.sweep_seconds = 0.05;
  o.on_dropped = [&](const std::string& gone) {
    std::lock_guard<std::mutex> lock(mutex);
    dropped.push_back(gone);
  };
  name::LocalNameServer ns(o);
  ns.client().register_name("/ghost", "tcp", "127.0.0.1", dead_port);
  for (int i = 0; i < 200; ++i) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (!dropped.empty()) break;
    }
    std::this_thread::sleep_for(10ms);
  }
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_EQ(dropped, std::vector<std::string>{"/ghost"});
  log::set_level(log::Level::Warn);
}

TEST(LocalNameServer, AnAddressInUseIsANetworkErrorNamingIt) {
  name::LocalNameServer first;
  name::LocalNameServerOptions o;
  o.at = first.contact();
  try {
    name::LocalNameServer second(o);
    FAIL() << "two name servers on one port";
  } catch (const NetworkError& e) {
    EXPECT_NE(std::string(e.what()).find(first.address()), std::string::npos) << e.what();
  }
}
