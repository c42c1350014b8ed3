// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// remote_controlboard reads the encoders (positions, speeds, accelerations) from the server's
// stateExt:o stream while it is fresh, and by RPC once it is 0.5 s old or for a field the server
// flags [fail].
#include <gtest/gtest.h>

#include <chrono>
#include <ostream>
#include <thread>
#include <vector>

#include "nws_test_util.hpp"
#include "robogene/dev/generated/controlboard_server.hpp"
#include "robogene/dev/generated/interfaces.hpp"
#include "robogene/dev/nws/controlboard_nws.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/dev/simulation_clock.hpp"
#include "robogene/network.hpp"
#include "robogene/port.hpp"

using namespace robogene;
using namespace robogene::dev;
using robogene::test::eventually;
using robogene::test::LocalNameServer;

namespace {

using Clock = std::chrono::steady_clock;

struct Readings {
  std::vector<double> pos, speeds, accs;
  double pos1 = 0, speed1 = 0, acc1 = 0;  // axis 1 by the single-axis methods
  bool operator==(const Readings& o) const {
    return pos == o.pos && speeds == o.speeds && accs == o.accs && pos1 == o.pos1 && speed1 == o.speed1 &&
           acc1 == o.acc1;
  }
};

void PrintTo(const Readings& r, std::ostream* os) {
  auto list = [os](const std::vector<double>& v) {
    *os << "(";
    for (double x : v) *os << x << " ";
    *os << ")";
  };
  *os << "positions ";
  list(r.pos);
  *os << " speeds ";
  list(r.speeds);
  *os << " accelerations ";
  list(r.accs);
  *os << " axis 1: " << r.pos1 << " " << r.speed1 << " " << r.acc1;
}

Readings read(IEncoders& enc) {
  Readings r;
  EXPECT_TRUE(enc.getEncoders(r.pos) && enc.getEncoderSpeeds(r.speeds) && enc.getEncoderAccelerations(r.accs));
  EXPECT_TRUE(enc.getEncoder(1, r.pos1) && enc.getEncoderSpeed(1, r.speed1) && enc.getEncoderAcceleration(1, r.acc1));
  return r;
}

// A test_motor on a manual clock: it moves only when the test says so.
struct ManualMotor {
  ManualMotor() {
    if (!device.open(Property::from_command_line({"--device", "test_motor", "--axes", "2", "--clock", "manual"}))) {
      throw Error(device.last_error());
    }
    device.view(driver);
    device.view(enc);
    device.view(vel);
    device.view(clock);
  }
  PolyDriver device;
  DeviceDriver* driver = nullptr;
  IEncoders* enc = nullptr;
  IVelocityControl* vel = nullptr;
  ISimulationClock* clock = nullptr;
};

}  // namespace

TEST(RemoteControlboard, ReadsTheEncodersFromTheStreamUntilItIsHalfASecondOld) {
  LocalNameServer ns;
  ManualMotor motor;
  ControlboardNws server;
  server.open(*motor.driver, ns.config("(name /motors)"));
  PolyDriver remote;
  ASSERT_TRUE(remote.open(ns.config("(device remote_controlboard) (remote /motors) (local /client)")))
      << remote.last_error();
  IEncoders* enc = nullptr;
  ASSERT_TRUE(remote.view(enc));

  // Axis 1 mid-ramp: 2.5 deg/s, 50 deg/s^2. The client soon reads what the device reads.
  ASSERT_TRUE(motor.vel->velocityMove(1, 5.0));
  ASSERT_TRUE(motor.clock->advance(0.05));
  const Readings streamed = read(*motor.enc);
  EXPECT_NEAR(streamed.speed1, 2.5, 1e-9);
  ASSERT_TRUE(eventually([&] { return read(*enc) == streamed; }));
  // RPC gives the same readings: wait for a few periods of the stream (0.02 s) to have come.
  std::this_thread::sleep_for(std::chrono::milliseconds(150));

  // Without the stream, the device moves on but the client keeps the last jointData, for 0.5 s:
  // these readings cannot have come by RPC.
  NameClient names = ns.client();
  ASSERT_TRUE(network::disconnect(names, "/motors/stateExt:o", "/client/stateExt:i").ok);
  const auto cut = Clock::now();
  ASSERT_TRUE(motor.clock->advance(1.0));  // cruising at 5 deg/s: no acceleration any more
  const Readings now = read(*motor.enc);
  ASSERT_FALSE(now == streamed);
  EXPECT_EQ(read(*enc), streamed);
  ASSERT_LT(Clock::now() - cut, std::chrono::milliseconds(400)) << "too slow to see the fresh stream";

  // Then the stream is stale and every reading comes by RPC.
  std::this_thread::sleep_until(cut + std::chrono::milliseconds(600));
  EXPECT_EQ(read(*enc), now);
  double v = 0;
  EXPECT_FALSE(enc->getEncoder(2, v));  // no axis 2, stream or not
}

TEST(RemoteControlboard, FieldsFlaggedFailAndMalformedMessagesGoByRpc) {
  LocalNameServer ns;
  NameClient names = ns.client();
  ManualMotor motor;
  ASSERT_TRUE(motor.enc->setEncoders({1.0, 2.0}));
  // A server of our own: RPC answered from test_motor, and a jointData stream written by hand.
  ControlboardServer dispatch(*motor.driver);
  Port rpc, command, state;
  rpc.set_reader([&](const Bottle& request, const MessageInfo&, Bottle* reply) {
    if (reply) *reply = dispatch.respond(request);
  });
  rpc.open("/fake/rpc:i", names);
  command.open("/fake/command:i", names);
  state.open("/fake/stateExt:o", names);
  PolyDriver remote;
  ASSERT_TRUE(remote.open(ns.config("(device remote_controlboard) (remote /fake) (local /client) (carrier tcp)")))
      << remote.last_error();
  IEncoders* enc = nullptr;
  ASSERT_TRUE(remote.view(enc));

  // Positions valid (and unlike the device's), speeds and accelerations flagged [fail].
  const Bottle message = Bottle::from_text(
      "(7.0 8.0) [ok] (99.0 99.0) [fail] (99.0 99.0) [fail] (0.0 0.0) [fail] (0.0 0.0) [fail] "
      "(0.0 0.0) [fail] (0.0 0.0) [fail] (0.0 0.0) [fail] (0.0 0.0) [fail] (0 0) [fail] (0 0) [fail]");
  std::vector<double> pos, speeds;
  ASSERT_TRUE(eventually([&] {
    state.write(message);
    return enc->getEncoders(pos) && pos == std::vector<double>{7.0, 8.0};
  }));
  ASSERT_TRUE(enc->getEncoderSpeeds(speeds));
  EXPECT_EQ(speeds, (std::vector<double>{0.0, 0.0}));  // the device's, by RPC
  double acc = -1;
  ASSERT_TRUE(enc->getEncoderAcceleration(0, acc));
  EXPECT_EQ(acc, 0.0);

  // Once the stream is stale, a malformed message (one axis too few) does not refresh it.
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  for (int i = 0; i < 5; ++i) {
    state.write(Bottle::from_text("(7.0) [ok]"));
    state.write(Bottle::from_text(
        "(7.0) [ok] (0.0) [ok] (0.0) [ok] (0.0) [ok] (0.0) [ok] (0.0) [ok] (0.0) [ok] (0.0) [ok] (0.0) [ok] (0) [ok] (0) [ok]"));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_TRUE(enc->getEncoders(pos));
  EXPECT_EQ(pos, (std::vector<double>{1.0, 2.0}));  // by RPC
  remote.close();
}
