// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The control core's loops and protections on a fake plant: moves, velocity timeout, the
// current limiter, faults, the coupled eye board's mixing.
#include <gtest/gtest.h>

#include "fake_board.hpp"

namespace rg_test {
namespace {

void set_mode(FakeBoard& b, unsigned axis, std::uint8_t mode) { b.command({ROBOGENE_CAN_CMD_SET_CONTROL_MODE, mode}, axis); }

TEST(CoreControl, PositionMoveReachesTheTargetAndReportsDone) {
  FakeBoard b;
  b.start();
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.command(position_move(10000, 2000));  // 20000 counts/s
  EXPECT_EQ(b.command({ROBOGENE_CAN_CMD_MOTION_DONE})->data[1], 0);
  b.run(0.25);
  EXPECT_GT(b.core.axes[0].measured, 2000);
  EXPECT_LT(b.core.axes[0].measured, 8000);
  b.run(1.0);
  EXPECT_NEAR(b.core.axes[0].measured, 10000, 20);
  EXPECT_EQ(b.command({ROBOGENE_CAN_CMD_MOTION_DONE})->data[1], 1);
  EXPECT_EQ(b.core.axes[1].measured, 0) << "the other axis stayed idle";
}

TEST(CoreControl, PositionMovesAreClampedToTheSoftwareLimitsAndIgnoredWhenIdle) {
  FakeBoard b;
  b.start();
  b.command(position_move(10000, 2000));
  b.run(0.5);
  EXPECT_EQ(b.core.axes[0].measured, 0);
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.command(position_move(90000, 4000));
  b.run(2.0);
  EXPECT_NEAR(b.core.axes[0].measured, 20000, 20);
}

TEST(CoreControl, VelocityModeStopsWhenTheHostFallsSilent) {
  FakeBoard b;
  b.start();
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_VELOCITY);
  for (int i = 0; i < 10; ++i) {
    b.command({ROBOGENE_CAN_CMD_VELOCITY_MOVE, 0xE8, 0x03, 100, 0});  // 10000 counts/s, 100000 counts/s^2
    b.run(0.02);
  }
  EXPECT_NEAR(b.core.axes[0].speed, 10000, 1500);
  b.run(0.5);
  const auto stopped = b.core.axes[0].measured;
  b.run(0.5);
  EXPECT_NEAR(b.core.axes[0].measured, stopped, 5) << "the 100 ms velocity timeout stopped the axis";
}

TEST(CoreControl, CurrentLimiterHoldsAStalledMotorAtItsLimit) {
  FakeBoard b;
  b.plant[0].stop_high = 100.0;  // blocked right away
  b.start();
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.command(position_move(10000, 2000));
  double peak_late = 0.0;
  for (int t = 0; t < 1000; ++t) {
    b.run(0.001);
    if (t > 50) peak_late = std::max(peak_late, std::fabs(b.plant[0].current_ma()));
  }
  EXPECT_GT(b.core.axes[0].output, 800) << "the position loop asks for far more";
  EXPECT_LE(peak_late, 1000.0 * 1.05);
  EXPECT_GE(peak_late, 1000.0 * 0.8) << "and the limiter still lets the motor push";
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_POSITION) << "a limited current is no fault";
}

TEST(CoreControl, CurrentTheLimiterCannotHoldIsAnOvercurrentFaultUntilForceIdle) {
  FakeBoard b;
  b.start();
  b.command(le32(ROBOGENE_CAN_CMD_SET_BROADCAST_POLICY, ROBOGENE_CAN_BROADCAST_MASK_STATUS));
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.plant[0].forced_current_ma = 3000;  // a shorted lead: current whatever the duty
  b.run(0.019);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_POSITION) << "19 ms may be a transient";
  b.sent.clear();
  b.run(0.002);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT);
  EXPECT_FALSE(b.plant[0].enabled) << "the bridge is off";
  ASSERT_FALSE(b.sent.empty());
  const auto& status = b.sent.back();
  EXPECT_EQ(status.data[ROBOGENE_CAN_STATUS_BROADCAST_FAULTS0_BYTE], ROBOGENE_CAN_AXIS_FAULTS_OVERCURRENT);
  EXPECT_EQ(status.data[ROBOGENE_CAN_STATUS_BROADCAST_MODE0_BYTE], ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT);
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT) << "only force_idle leaves a fault";
  b.plant[0].forced_current_ma.reset();
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_FORCE_IDLE);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_IDLE);
  b.run(0.01);
  EXPECT_EQ(b.core.axes[0].faults, 0);
}

TEST(CoreControl, SupplyAndBridgeFaultsStopRunningAxesAndOnlyFlagIdleOnes) {
  FakeBoard b;
  b.start();
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.supply = 8000;
  b.run(0.001);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT);
  EXPECT_EQ(b.core.axes[0].faults, ROBOGENE_CAN_AXIS_FAULTS_UNDERVOLTAGE);
  EXPECT_EQ(b.mode(1), ROBOGENE_CAN_CONTROL_MODE_IDLE);
  EXPECT_EQ(b.core.axes[1].faults, ROBOGENE_CAN_AXIS_FAULTS_UNDERVOLTAGE);
  b.supply = 12000;
  b.run(0.001);
  EXPECT_EQ(b.core.axes[1].faults, 0) << "an idle axis reports the condition while it lasts";
  EXPECT_EQ(b.core.axes[0].faults, ROBOGENE_CAN_AXIS_FAULTS_UNDERVOLTAGE) << "a stopped one keeps why";
  set_mode(b, 1, ROBOGENE_CAN_CONTROL_MODE_VELOCITY);
  b.fault = true;
  b.supply = 17000;
  b.run(0.001);
  EXPECT_EQ(b.mode(1), ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT);
  EXPECT_EQ(b.core.axes[1].faults, ROBOGENE_CAN_AXIS_FAULTS_EXTERNAL | ROBOGENE_CAN_AXIS_FAULTS_OVERVOLTAGE);
}

TEST(CoreControl, EyeBoardMixesVersionAndVergenceIntoTheMotors) {
  FakeBoard b(RG_COUPLING_VERSION_VERGENCE);
  b.start();
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  set_mode(b, 1, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.command(position_move(6000, 2000), 0);  // version: left + right counts
  b.command(position_move(2000, 2000), 1);  // vergence: left - right
  b.run(2.0);
  EXPECT_NEAR(b.plant[0].counts, 4000, 20);
  EXPECT_NEAR(b.plant[1].counts, 2000, 20);
  EXPECT_NEAR(b.core.axes[0].measured, 6000, 20);
  EXPECT_NEAR(b.core.axes[1].measured, 2000, 20);
}

TEST(CoreControl, SetEncoderPositionShiftsTheAxisWithoutMovingIt) {
  FakeBoard b;
  b.start();
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.run(0.1);
  b.command(le32(ROBOGENE_CAN_CMD_SET_ENCODER_POSITION, 5000));
  b.run(0.5);
  EXPECT_EQ(b.core.axes[0].measured, 5000);
  EXPECT_NEAR(b.plant[0].counts, 0, 2);
}

}  // namespace
}  // namespace rg_test
