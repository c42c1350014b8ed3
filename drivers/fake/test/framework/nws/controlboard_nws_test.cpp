// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The control board on real ports: controlBoard_nws_yarp serving test_motor, remote_controlboard
// using it, all registered with a real name server on loopback.
#include <gtest/gtest.h>

#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include "nws_test_util.hpp"
#include "robogene/dev/generated/interfaces.hpp"
#include "robogene/dev/nws/network_devices.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/envelope.hpp"
#include "robogene/error.hpp"
#include "robogene/network.hpp"
#include "robogene/port.hpp"

using namespace robogene;
using namespace robogene::dev;
using robogene::test::eventually;
using robogene::test::LocalNameServer;

namespace {

struct Reading {
  std::vector<double> first, later;
  double elapsed_first = 0;
  bool done_after_start = true;
};

// Paper section 3.3 as written, for any device: the caller decides what `device` is.
Reading section_33(PolyDriver& device) {
  IPositionControl* ipos = 0;
  device.view(ipos);
  IVelocityControl* ivel = 0;
  device.view(ivel);
  EXPECT_NE(ipos, nullptr);
  EXPECT_NE(ivel, nullptr);
  Reading r;
  if (!ipos || !ivel) return r;

  const auto start = std::chrono::steady_clock::now();
  ipos->setRefAcceleration(0, 100);
  ipos->setRefSpeed(0, 5);
  ipos->positionMove(0, 40);

  ivel->setRefAcceleration(1, 100);
  ivel->velocityMove(1, 5);

  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  IEncoders* ienc = nullptr;
  EXPECT_TRUE(device.view(ienc));
  if (!ienc) return r;
  EXPECT_TRUE(ienc->getEncoders(r.first));
  r.elapsed_first = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ipos->checkMotionDone(0, r.done_after_start);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_TRUE(ienc->getEncoders(r.later));
  return r;
}

void expect_encoders_follow(const Reading& r, double lag) {
  ASSERT_EQ(r.first.size(), 2u);
  ASSERT_EQ(r.later.size(), 2u);
  // 0.4 s after the commands, less a possible stream lag: at least (0.4 - lag - ramp) * 5 deg.
  EXPECT_GT(r.first[0], (0.4 - lag - 0.05) * 5.0);
  EXPECT_LE(r.first[0], r.elapsed_first * 5.0 + 1e-9);
  EXPECT_GT(r.first[1], (0.4 - lag - 0.05) * 5.0);
  EXPECT_LE(r.first[1], r.elapsed_first * 5.0 + 1e-9);
  EXPECT_GT(r.later[0], r.first[0] + 1.0);  // 0.3 s later at 5 deg/s
  EXPECT_GT(r.later[1], r.first[1] + 1.0);
  EXPECT_FALSE(r.done_after_start);  // 40 deg at 5 deg/s takes 8 s
}

struct ServedMotor {
  explicit ServedMotor(LocalNameServer& ns, const std::string& extra = "") {
    Property config = ns.config("(device controlBoard_nws_yarp) (subdevice test_motor) (axes 2) (name /motors) " + extra);
    if (!server.open(config)) throw Error(server.last_error());
  }
  PolyDriver server;
};

}  // namespace

TEST(ControlboardNws, PaperSection33RunsUnchangedLocallyAndThroughTheNetwork) {
  LocalNameServer ns;
  PolyDriver local;
  ASSERT_TRUE(local.open(ns.config("(device test_motor) (axes 2)"))) << local.last_error();
  expect_encoders_follow(section_33(local), 0.0);

  ServedMotor served(ns);
  PolyDriver remote;
  ASSERT_TRUE(remote.open(ns.config("(device remote_controlboard) (remote /motors) (local /paper)")))
      << remote.last_error();
  expect_encoders_follow(section_33(remote), 0.1);
}

TEST(ControlboardNws, TheRemoteDeviceAlsoWorksOverTcpStreams) {
  LocalNameServer ns;
  ServedMotor served(ns);
  PolyDriver remote;
  ASSERT_TRUE(remote.open(ns.config("(device remote_controlboard) (remote /motors) (local /paper) (carrier tcp)")))
      << remote.last_error();
  expect_encoders_follow(section_33(remote), 0.1);
  IVelocityControl* ivel = nullptr;
  ASSERT_TRUE(remote.view(ivel));
  EXPECT_FALSE(ivel->velocityMove(2, 1.0));  // axis 2 of 2 does not exist
  double v = 0;
  ASSERT_TRUE(ivel->getRefVelocity(1, v));
  EXPECT_EQ(v, 5.0);  // sent on the command port, read back by RPC
}

TEST(ControlboardNws, OpensYarpsPortsAndUnregistersThemOnClose) {
  LocalNameServer ns;
  NameClient names = ns.client();
  {
    ServedMotor served(ns);
    INetworkWrapper* wrapper = nullptr;
    ASSERT_TRUE(served.server.view(wrapper));
    EXPECT_EQ(wrapper->port_names(), (std::vector<std::string>{"/motors/rpc:i", "/motors/command:i",
                                                               "/motors/state:o", "/motors/stateExt:o"}));
    for (const auto& p : wrapper->port_names()) EXPECT_TRUE(names.query(p).has_value()) << p;
  }
  for (const char* p : {"/motors/rpc:i", "/motors/command:i", "/motors/state:o", "/motors/stateExt:o"}) {
    EXPECT_FALSE(names.query(p).has_value()) << p;
  }
}

TEST(ControlboardNws, StatePortsStreamEncodersWithEnvelopesAtThePeriod) {
  LocalNameServer ns;
  ServedMotor served(ns, "(period 0.05)");
  NameClient names = ns.client();

  std::mutex m;
  std::vector<std::pair<Stamp, Bottle>> states, exts;
  Port state_in, ext_in;
  state_in.set_reader([&](const Bottle& b, const MessageInfo& info, Bottle*) {
    auto s = Stamp::parse(info.envelope);
    std::lock_guard<std::mutex> lock(m);
    if (s) states.emplace_back(*s, b);
  });
  ext_in.set_reader([&](const Bottle& b, const MessageInfo& info, Bottle*) {
    auto s = Stamp::parse(info.envelope);
    std::lock_guard<std::mutex> lock(m);
    if (s) exts.emplace_back(*s, b);
  });
  state_in.open("/reader/state:i", names);
  ext_in.open("/reader/stateExt:i", names);
  ASSERT_TRUE(network::connect(names, "/motors/state:o", "/reader/state:i").ok);
  ASSERT_TRUE(network::connect(names, "/motors/stateExt:o", "/reader/stateExt:i", "udp").ok);
  ASSERT_TRUE(eventually([&] {
    std::lock_guard<std::mutex> lock(m);
    return states.size() >= 11 && exts.size() >= 11;
  }));
  std::lock_guard<std::mutex> lock(m);
  // Consecutive sequence numbers, 0.05 s apart on average (a loaded machine may be late once).
  const auto& first = states.front().first;
  const auto& tenth = states[10].first;
  EXPECT_EQ(tenth.sequence, first.sequence + 10);
  // The schedule does not drift: ten periods take 0.5 s, more only when a loaded machine skips ticks.
  EXPECT_GE(tenth.time - first.time, 0.45);
  EXPECT_LE(tenth.time - first.time, 0.8);
  EXPECT_EQ(states.front().second.to_text(), "0.0 0.0");
  // jointData: 22 items, positions first and flagged [ok].
  const Bottle& ext = exts.front().second;
  ASSERT_EQ(ext.size(), 22u);
  EXPECT_EQ(ext[0].to_text(), "(0.0 0.0)");
  EXPECT_EQ(ext[1].to_text(), "[ok]");
  state_in.close();
  ext_in.close();
}

TEST(ControlboardNws, CommandPortTakesStreamedMoves) {
  LocalNameServer ns;
  ServedMotor served(ns);
  NameClient names = ns.client();
  Port out;
  out.open("/commander", names);
  out.add_output("/motors/command:i", "udp");
  // What YARP's remote_controlboard sends for velocityMove(1, 7.5) (reference 5.5).
  Bottle message = Bottle::from_text("([vmo] 1) (7.5)");
  ASSERT_TRUE(out.write(message));
  auto rpc = ns.client().query("/motors/rpc:i");
  ASSERT_TRUE(rpc);
  EXPECT_TRUE(eventually([&] {
    Bottle reply = network::rpc(*rpc, Bottle::from_text("[get] [vmo] 1"));
    return reply.size() >= 3 && reply[2].to_text() == "7.5";
  }));
  // The group form a YARP proxy sends, on the command port and by RPC.
  ASSERT_TRUE(out.write(Bottle::from_text("([vmog] 2 (0 1)) (2.5 -1.0)")));
  EXPECT_TRUE(eventually([&] {
    Bottle reply = network::rpc(*rpc, Bottle::from_text("[get] [vmos]"));
    return reply.size() >= 3 && reply[2].to_text() == "(2.5 -1.0)";
  }));
  EXPECT_EQ(network::rpc(*rpc, Bottle::from_text("[set] [posg] 1 (1) (20.0)")).to_text(), "[ok]");
  EXPECT_EQ(network::rpc(*rpc, Bottle::from_text("[get] [pos] 1")).size(), 7u);
  EXPECT_EQ(network::rpc(*rpc, Bottle::from_text("[get] [pos] 1"))[2].to_text(), "20.0");
  EXPECT_EQ(network::rpc(*rpc, Bottle::from_text("[set] [posg] 1 (5) (20.0)")).to_text(), "[fail]");
  out.close();
}

TEST(ControlboardNws, SinglePortAnswersRpcAndStreamsToReversedReaders) {
  LocalNameServer ns;
  ServedMotor served(ns, "(single_port)");
  NameClient names = ns.client();
  INetworkWrapper* wrapper = nullptr;
  ASSERT_TRUE(served.server.view(wrapper));
  EXPECT_EQ(wrapper->port_names(), std::vector<std::string>{"/motors"});
  auto at = names.query("/motors");
  ASSERT_TRUE(at);
  Bottle axes = network::rpc(*at, Bottle::from_text("[get] [axes]"));
  ASSERT_EQ(axes.size(), 7u) << axes.to_text();  // [is] [axes] 2 [tsta] n t [ok]
  EXPECT_EQ(axes[0].to_text(), "[is]");
  EXPECT_EQ(axes[2].to_text(), "2");
  EXPECT_EQ(network::rpc(*at, Bottle::from_text("[set] [pos] 0 100.0")).to_text(), "[ok]");

  // A reader that adds itself as the port's output sees the encoder vector streamed.
  std::mutex m;
  std::vector<Bottle> seen;
  Port in;
  in.set_reader([&](const Bottle& b, const MessageInfo&, Bottle*) {
    std::lock_guard<std::mutex> lock(m);
    seen.push_back(b);
  });
  in.open("/watcher", names);
  ASSERT_TRUE(network::connect(names, "/motors", "/watcher").ok);
  ASSERT_TRUE(eventually([&] {
    std::lock_guard<std::mutex> lock(m);
    return seen.size() >= 3;
  }));
  {
    std::lock_guard<std::mutex> lock(m);
    EXPECT_EQ(seen.back().size(), 2u);
  }
  in.close();  // not while holding `m`: the input thread may be in the reader, waiting for it
}

TEST(ControlboardNws, BadConfigurationsSayWhatIsWrong) {
  LocalNameServer ns;
  PolyDriver d;
  EXPECT_FALSE(d.open(ns.config("(device controlBoard_nws_yarp) (name /m)")));
  EXPECT_NE(d.last_error().find("no 'subdevice' key"), std::string::npos) << d.last_error();
  EXPECT_FALSE(d.open(ns.config("(device controlBoard_nws_yarp) (subdevice test_motor) (name motors)")));
  EXPECT_NE(d.last_error().find("'motors' is not a port name"), std::string::npos) << d.last_error();
  EXPECT_FALSE(d.open(ns.config("(device controlBoard_nws_yarp) (subdevice test_motor) (name /m) (period 0)")));
  EXPECT_NE(d.last_error().find("period"), std::string::npos) << d.last_error();
  EXPECT_FALSE(d.open(ns.config("(device controlBoard_nws_yarp) (subdevice dragonfly) (name /m)")));
  EXPECT_NE(d.last_error().find("unknown device 'dragonfly'"), std::string::npos) << d.last_error();
  // No server under that name: the client says which port it could not reach.
  EXPECT_FALSE(d.open(ns.config("(device remote_controlboard) (remote /nobody) (local /me)")));
  EXPECT_NE(d.last_error().find("/nobody/rpc:i"), std::string::npos) << d.last_error();
  EXPECT_FALSE(ns.client().query("/me/rpc:o").has_value());  // cleaned up after the failure
}
