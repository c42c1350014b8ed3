// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Attack: a flood fills a port's inputs, so the name server's liveness probe finds it accepting
// and hanging up at once. That used to count as "not a port": the name was unregistered and
// never came back, and after the flood nobody could reach the port by name. The probe must keep
// a busy port's name, and a port whose name was lost anyway must register again.
#include <gtest/gtest.h>

#include "robogene/testing/hostile_util.hpp"
#include "robogene/log.hpp"
#include "robogene/name/local_name_server.hpp"
#include "robogene/name_client.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

// A name server that probes with the real tcp probe, at once and every time.
name::LocalNameServerOptions probing() {
  name::LocalNameServerOptions o;
  o.probe_liveness = true;
  o.probe_answer_timeout_ms = 1000;
  o.service.stale_grace_seconds = 0;
  o.service.recheck_seconds = 0;
  return o;
}

}  // namespace

TEST(HostileLostName, ProbeKeepsTheNameOfAPortTooBusyToAnswer) {
  log::set_level(log::Level::Error);
  name::LocalNameServer ns(probing());
  PortOptions o;
  o.max_inputs = 8;
  o.registration_check = 0ms;  // only the probe's verdict is under test here
  Port r(o);
  r.open("/busy", ns.client());
  const ProcessUsage before = ProcessUsage::now();
  // The flood: 8 idle connections fill the port; every further one is accepted and closed.
  std::vector<net::TcpStream> flood;
  for (int i = 0; i < 8; ++i) {
    flood.push_back(connect_to(r));
    send(flood.back(), hello(carrier::kTcpSpecifier, "/flood" + std::to_string(i)));
    read_n(flood.back(), 8);
  }
  std::this_thread::sleep_for(200ms);
  auto gone = ns.service().sweep();  // probes /busy while it is full
  EXPECT_TRUE(std::find(gone.begin(), gone.end(), "/busy") == gone.end())
      << "the probe unregistered a port that was alive but busy";
  flood.clear();
  auto c = ns.client().query("/busy");
  ASSERT_TRUE(c.has_value()) << "/busy is unreachable by name after the flood";
  EXPECT_EQ(c->port, r.contact().port);
  const ProcessUsage after = usage_when([&](const ProcessUsage& u) { return u.threads <= before.threads + 1; });
  EXPECT_LE(after.threads, before.threads + 1) << after.text();
  EXPECT_TRUE(legit_client_served(r));
}

TEST(HostileLostName, ProbeStillDropsANameNobodyListensOn) {
  log::set_level(log::Level::Error);
  name::LocalNameServer ns(probing());
  int free_port;
  {
    auto l = net::TcpListener::listen({"127.0.0.1", 0});
    free_port = l.local().port;
  }
  ns.client().register_name("/gone", "tcp", "127.0.0.1", free_port);
  auto gone = ns.service().sweep();
  EXPECT_TRUE(std::find(gone.begin(), gone.end(), "/gone") != gone.end());
}

// A listener that accepts (the kernel's backlog) but never answers the handshake is no port: every
// port answers from a thread of its own, however busy. Its name goes, as it did before the probe
// learnt to spare ports that hang up when full.
TEST(HostileLostName, ProbeDropsAListenerThatNeverAnswers) {
  log::set_level(log::Level::Error);
  name::LocalNameServer ns(probing());
  auto impostor = net::TcpListener::listen({"127.0.0.1", 0});  // never accepts
  ns.client().register_name("/impostor", "tcp", "127.0.0.1", impostor.local().port);
  auto gone = ns.service().sweep();
  EXPECT_TRUE(std::find(gone.begin(), gone.end(), "/impostor") != gone.end())
      << "a listener that never answered the handshake was kept as a busy port";
}

TEST(HostileLostName, APortWhoseNameWasLostRegistersAgain) {
  log::set_level(log::Level::Error);
  name::LocalNameServer ns(probing());
  PortOptions o;
  o.registration_check = 200ms;
  Port r(o);
  r.open("/lost", ns.client());
  ns.client().unregister("/lost");  // as the old probe did during a flood
  ASSERT_FALSE(ns.client().query("/lost").has_value());
  std::optional<Contact> back;
  ASSERT_TRUE(wait_until([&] { return (back = ns.client().query("/lost")).has_value(); }))
      << "the port never registered its name again";
  EXPECT_EQ(back->port, r.contact().port);
  // And it is reachable by name, as any YARP writer would find it.
  Port w;
  w.open("/finder", ns.client());
  w.add_output("/lost");
  std::thread t([&] { w.write(Bottle{Value("found")}); });
  Bottle b;
  EXPECT_TRUE(r.read(b, false, 5000ms));
  t.join();
  EXPECT_EQ(b.to_text(), "found");
  r.close();
  EXPECT_FALSE(ns.client().query("/lost").has_value()) << "a closed port does not come back";
}

// Each open port used to keep its own thread for these checks: a process with many ports had
// as many more threads. Now one thread serves every port of the process.
TEST(HostileLostName, ManyPortsShareOneRegistrationThread) {
  log::set_level(log::Level::Error);
  name::LocalNameServer ns;  // no liveness probe: its connections to the ports would be threads too
  PortOptions o;
  o.registration_check = 200ms;
  const ProcessUsage before = ProcessUsage::now();
  constexpr std::size_t kPorts = 20;
  std::vector<std::unique_ptr<Port>> ports;
  for (std::size_t i = 0; i < kPorts; ++i) {
    ports.push_back(std::make_unique<Port>(o));
    ports.back()->open("/many" + std::to_string(i), ns.client());
  }
  // An acceptor thread per port, one registration thread and the handshake-deadline timer.
  const ProcessUsage during =
      usage_when([&](const ProcessUsage& u) { return u.threads <= before.threads + kPorts + 1 + kDeadlineTimerThread; });
  EXPECT_LE(during.threads, before.threads + kPorts + 1 + kDeadlineTimerThread) << "before: " << before.text() << "; during: " << during.text();
  // The one thread still finds every lost name.
  ns.client().unregister("/many3");
  ns.client().unregister("/many17");
  EXPECT_TRUE(wait_until([&] {
    return ns.client().query("/many3").has_value() && ns.client().query("/many17").has_value();
  })) << "the lost names were not registered again";
  ports.clear();
  EXPECT_FALSE(ns.client().query("/many3").has_value()) << "closed ports do not come back";
  const ProcessUsage after = usage_when([&](const ProcessUsage& u) { return u.threads <= before.threads + 1 + kDeadlineTimerThread; });
  EXPECT_LE(after.threads, before.threads + 1 + kDeadlineTimerThread) << after.text();
}
