// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// YARP 3's PID offset, enable, disable and reset requests over RPC, against test_motor: the
// replies in the shapes of RPCMessagesParser::handlePidMsg, and the model's behaviour through the
// generated client and server (docs/devices.md, test_motor). Python's twin is
// tests/codegen/test_python_pid_switches.py.
#include <gtest/gtest.h>

#include "robogene/testing/vector_cases.hpp"
#include "in_process_board.hpp"

#include <cmath>
#include <memory>
#include <string>

#include "robogene/dev/generated/controlboard_client.hpp"
#include "robogene/dev/generated/controlboard_server.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/dev/simulation_clock.hpp"

using namespace robogene;
using namespace robogene::dev;

namespace {

// The in-process board (support/in_process_board.hpp) with the questions these tests ask.
struct Remote : robogene::test::InProcessBoard {
  std::string ask(const std::string& text) { return server->respond(Bottle::from_text(text)).to_text(); }
  bool enabled(PidType t, int j) {
    bool on = false;
    EXPECT_TRUE(client->isPidEnabled(t, j, on));
    return on;
  }
  ControlMode mode(int j) {
    ControlMode m{};
    EXPECT_TRUE(client->getControlMode(j, m));
    return m;
  }
  double encoder(int j) {
    double v = NAN;
    EXPECT_TRUE(client->getEncoder(j, v));
    return v;
  }
};

}  // namespace

TEST(PidSwitchesRpc, RepliesHaveYarpsShapes) {
  Remote r;
  EXPECT_EQ(r.ask("[get] [pid] [ena] [pos] 0"), "[is] [pid] 1 [ok]");
  // isPidEnabled's bool is an int32, as handlePidMsg's addInt32; no stamp.
  EXPECT_EQ(robogene::testing::to_hex(r.server->respond(Bottle::from_text("[get] [pid] [ena] [vel] 2")).to_bytes()),
            "0001000004000000" "0900000069730000" "0900000070696400" "0100000001000000" "090000006f6b0000");
  EXPECT_EQ(r.ask("[set] [pid] [off] [pos] 1 2.5"), "[ok]");
  EXPECT_EQ(r.ask("[get] [pid] [pid] [pos] 1"), "[is] [pid] (0.0 0.0 0.0 0.0 0.0 2.5 0.0 0.0 0.0 0.0) [ok]");
  EXPECT_EQ(r.ask("[set] [pid] [dis] [trq] 0"), "[ok]");
  EXPECT_EQ(r.ask("[get] [pid] [ena] [trq] 0"), "[is] [pid] 0 [ok]");
  EXPECT_EQ(r.ask("[set] [pid] [ena] [trq] 0"), "[ok]");
  EXPECT_EQ(r.ask("[set] [pid] [res] [pos] 0"), "[ok]");
  // Malformed or impossible: a missing value, a PID type that does not exist, the current loop.
  EXPECT_EQ(r.ask("[set] [pid] [off] [pos] 1"), "[fail]");
  EXPECT_EQ(r.ask("[set] [pid] [ena] [xyz] 1"), "[fail]");
  EXPECT_EQ(r.ask("[get] [pid] [ena] [cur] 1"), "[fail]");
  EXPECT_EQ(r.ask("[set] [pid] [dis] [pos] 3"), "[fail]");  // no axis 3
}

TEST(PidSwitchesRpc, OffsetIsTheGainsOffsetForEveryController) {
  Remote r;
  IPidControl& pid = *r.client;
  const Pid gains{6000, 500, 5, 1333, 1333, 0, 8, 0.5, -0.5, 1};
  ASSERT_TRUE(pid.setPid(PidType::velocity, 2, gains));
  ASSERT_TRUE(pid.setPidOffset(PidType::velocity, 2, -7.0));
  Pid back;
  ASSERT_TRUE(pid.getPid(PidType::velocity, 2, back));
  Pid expected = gains;
  expected.offset = -7.0;
  EXPECT_EQ(back, expected);
  ASSERT_TRUE(pid.setPidOffset(PidType::current, 0, 3.0));  // the current loop's gains are kept too
  ASSERT_TRUE(pid.getPid(PidType::current, 0, back));
  EXPECT_EQ(back.offset, 3.0);
  EXPECT_FALSE(pid.setPidOffset(PidType::velocity, 2, NAN));
  EXPECT_FALSE(pid.setPidOffset(PidType::velocity, 3, 1.0));
  ASSERT_TRUE(pid.getPid(PidType::velocity, 2, back));
  EXPECT_EQ(back, expected);
}

TEST(PidSwitchesRpc, ADisabledLoopFreesItsAxisAndCannotRunUntilEnabled) {
  Remote r;
  IPidControl& pid = *r.client;
  IPositionControl& pos = *r.client;
  IVelocityControl& vel = *r.client;
  ITorqueControl& trq = *r.client;
  IControlMode& mode = *r.client;
  for (PidType t : {PidType::position, PidType::velocity, PidType::torque}) EXPECT_TRUE(r.enabled(t, 1));
  bool on = true;
  EXPECT_FALSE(pid.isPidEnabled(PidType::current, 1, on));  // no current loop
  EXPECT_FALSE(pid.enablePid(PidType::current, 1));
  EXPECT_FALSE(pid.disablePid(PidType::current, 1));

  // Axis 1 moving to 40: disabling its position loop frees it where it is.
  ASSERT_TRUE(pos.positionMove(1, 40.0));
  ASSERT_TRUE(r.clock->advance(1.0));
  const double there = r.encoder(1);
  ASSERT_GT(there, 1.0);
  ASSERT_TRUE(pid.disablePid(PidType::position, 1));
  EXPECT_FALSE(r.enabled(PidType::position, 1));
  EXPECT_EQ(r.mode(1), ControlMode::idle);
  ASSERT_TRUE(r.clock->advance(1.0));
  EXPECT_EQ(r.encoder(1), there);

  // Nothing may run it again: single and all-axes moves, the mode, a PID query of the loop.
  EXPECT_FALSE(pos.positionMove(1, 10.0));
  EXPECT_FALSE(pos.relativeMove(1, 1.0));
  EXPECT_FALSE(pos.positionMove(std::vector<double>{5.0, 5.0, 5.0}));  // axis 1 in it: none moves
  EXPECT_FALSE(mode.setControlMode(1, ControlMode::position));
  EXPECT_FALSE(mode.setControlModes({ControlMode::idle, ControlMode::position, ControlMode::idle}));
  double ref = 0;
  EXPECT_FALSE(pid.getPidReference(PidType::position, 1, ref));
  EXPECT_EQ(r.mode(0), ControlMode::position);
  EXPECT_EQ(r.mode(1), ControlMode::idle);
  double target = 0;
  ASSERT_TRUE(pos.getTargetPosition(0, target));
  EXPECT_EQ(target, 0.0);
  // Other loops and other axes still work.
  ASSERT_TRUE(vel.velocityMove(1, 2.0));
  EXPECT_EQ(r.mode(1), ControlMode::velocity);
  ASSERT_TRUE(pos.positionMove(0, 3.0));

  ASSERT_TRUE(pid.enablePid(PidType::position, 1));
  EXPECT_TRUE(r.enabled(PidType::position, 1));
  EXPECT_EQ(r.mode(1), ControlMode::velocity);  // enabling does not take the axis over
  ASSERT_TRUE(pos.positionMove(1, 10.0));
  EXPECT_EQ(r.mode(1), ControlMode::position);

  // A loop the axis does not run is only switched off; the torque loop the same way.
  ASSERT_TRUE(pid.disablePid(PidType::velocity, 1));
  EXPECT_EQ(r.mode(1), ControlMode::position);
  EXPECT_FALSE(vel.velocityMove(1, 1.0));
  ASSERT_TRUE(trq.setRefTorque(2, 0.5));
  ASSERT_TRUE(pid.disablePid(PidType::torque, 2));
  EXPECT_EQ(r.mode(2), ControlMode::idle);
  EXPECT_FALSE(trq.setRefTorque(2, 0.5));
  EXPECT_FALSE(mode.setControlMode(2, ControlMode::torque));
}

TEST(PidSwitchesRpc, ResetMakesWhatTheRunningLoopMeasuresItsReference) {
  Remote r;
  IPidControl& pid = *r.client;
  IPositionControl& pos = *r.client;
  IVelocityControl& vel = *r.client;
  IEncoders& enc = *r.client;

  // Position: mid-move, the target becomes the present position, held from standstill.
  ASSERT_TRUE(pos.positionMove(0, 40.0));
  ASSERT_TRUE(r.clock->advance(1.0));
  double err = 0;
  ASSERT_TRUE(pid.getPidError(PidType::position, 0, err));
  ASSERT_GT(err, 1.0);
  ASSERT_TRUE(pid.resetPid(PidType::position, 0));
  const double there = r.encoder(0);
  double target = 0, speed = 1;
  ASSERT_TRUE(pos.getTargetPosition(0, target) && enc.getEncoderSpeed(0, speed));
  EXPECT_EQ(target, there);
  EXPECT_EQ(speed, 0.0);
  ASSERT_TRUE(pid.getPidError(PidType::position, 0, err));
  EXPECT_EQ(err, 0.0);
  ASSERT_TRUE(r.clock->advance(1.0));
  EXPECT_EQ(r.encoder(0), there);
  bool done = false;
  ASSERT_TRUE(pos.checkMotionDone(0, done));
  EXPECT_TRUE(done);

  // Velocity: mid-ramp, the present speed becomes the command and the ramp ends there.
  ASSERT_TRUE(vel.velocityMove(1, 10.0));
  ASSERT_TRUE(r.clock->advance(0.1));  // 5 deg/s of the 10, at 50 deg/s^2
  ASSERT_TRUE(pid.resetPid(PidType::velocity, 1));
  double ref = 0;
  ASSERT_TRUE(enc.getEncoderSpeed(1, speed) && pid.getPidReference(PidType::velocity, 1, ref));
  EXPECT_NEAR(speed, 5.0, 1e-9);
  EXPECT_EQ(ref, speed);
  ASSERT_TRUE(vel.getRefVelocity(1, ref));
  EXPECT_EQ(ref, speed);
  ASSERT_TRUE(r.clock->advance(1.0));
  double later = 0;
  ASSERT_TRUE(enc.getEncoderSpeed(1, later));
  EXPECT_EQ(later, speed);

  // A loop the axis does not run has nothing to reset; the torque loop follows its reference.
  ASSERT_TRUE(pid.resetPid(PidType::torque, 1));
  ASSERT_TRUE(enc.getEncoderSpeed(1, later));
  EXPECT_EQ(later, speed);
  EXPECT_FALSE(pid.resetPid(PidType::current, 1));
}
