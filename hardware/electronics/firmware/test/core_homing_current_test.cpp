// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The homing current limit: while an axis seeks its hard stop its motors are held to the homing
// run's current limit, so that the stop is pressed with that torque and not the run limit's; every
// way out of the seek (the stop found, a timeout, a mode change) is back at the run limit.
#include <gtest/gtest.h>

#include "fake_board.hpp"

namespace rg_test {
namespace {

constexpr std::int32_t kRunLimit = 1000;     // FakeBoard's per-motor limit
constexpr std::int32_t kHomingLimit = 300;   // the plant would draw 1500 mA pushing at the homing PWM

std::vector<std::uint8_t> calibrate() {
  return {ROBOGENE_CAN_CMD_CALIBRATE_ENCODER, ROBOGENE_CAN_CALIBRATION_TYPE_HARD_STOP, 0, 0, 0, 0};
}

struct HomingBoard : FakeBoard {
  explicit HomingBoard(bool stop = true) {
    params.axes[0].homing = rg_homing_config_t{+1, 5000.0f, 250, 15000, 1000, 5000, kHomingLimit};
    plant[0].counts = 3000;
    if (stop) plant[0].stop_high = 10000;  // stop_position 15000 there
  }
};

// The currents motor m draws while its axis presses the stop, seeking, after `settle` periods on it.
std::vector<double> pressing_currents(FakeBoard& b, unsigned m, unsigned axis, int settle = 10) {
  std::vector<double> out;
  int on_stop = 0;
  for (int t = 0; t < 6000 && b.core.axes[axis].homing.phase == RG_HOMING_SEEK; ++t) {
    b.run(0.001);
    const bool pressing = b.plant[m].stop_high && b.plant[m].counts >= *b.plant[m].stop_high;
    on_stop = pressing ? on_stop + 1 : 0;
    if (on_stop > settle && b.core.axes[axis].homing.phase == RG_HOMING_SEEK) out.push_back(b.plant[m].current_ma());
  }
  return out;
}

// Drives axis 0 of a homed board into its stop in position mode; the current it settles at.
double pushing_current(FakeBoard& b) {
  b.command(position_move(19000, 2000));  // the stop reads 15000 after homing: 4000 counts into it
  b.run(1.0);
  return b.plant[0].current_ma();
}

TEST(CoreHomingCurrent, PressesTheStopWithTheHomingLimitNotTheRunLimit) {
  HomingBoard b;
  b.start();
  ASSERT_FALSE(b.command(calibrate()));
  const auto currents = pressing_currents(b, 0, 0);
  ASSERT_GE(currents.size(), 20u) << "the stall is detected after 50 periods pressing the stop";
  EXPECT_EQ(b.core.axes[0].homing.phase, RG_HOMING_BACKOFF);
  for (double i : currents) {
    EXPECT_LE(i, kHomingLimit * 1.05);
    EXPECT_GE(i, kHomingLimit * 0.8) << "it pushes with what the limit allows";
  }
}

TEST(CoreHomingCurrent, TheRunLimitIsBackOnceTheStopIsFound) {
  HomingBoard b;
  b.start();
  b.command(calibrate());
  b.run(0.5);
  EXPECT_EQ(b.core.motors[0].active_limit_ma, kHomingLimit);
  EXPECT_EQ(b.core.motors[1].active_limit_ma, kRunLimit) << "the other axis's motor does not home";
  pressing_currents(b, 0, 0);
  b.run(0.001);
  EXPECT_EQ(b.core.motors[0].active_limit_ma, kRunLimit) << "backing off runs at the run limit";
  b.run(3.0);
  ASSERT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_POSITION);
  EXPECT_NEAR(pushing_current(b), kRunLimit, 0.1 * kRunLimit) << "position mode pushes with the run limit again";
}

TEST(CoreHomingCurrent, AnInterruptedHomingLeavesTheRunLimit) {
  HomingBoard b;
  b.start();
  b.command(calibrate());
  b.run(0.2);
  ASSERT_EQ(b.core.motors[0].active_limit_ma, kHomingLimit);
  b.command({ROBOGENE_CAN_CMD_SET_CONTROL_MODE, ROBOGENE_CAN_CONTROL_MODE_POSITION});
  b.run(0.001);
  EXPECT_EQ(b.core.motors[0].active_limit_ma, kRunLimit);
}

TEST(CoreHomingCurrent, AFailedHomingLeavesTheRunLimit) {
  HomingBoard b(false);
  b.start();
  b.command(calibrate());
  b.run(5.2);
  ASSERT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_NOT_CONFIGURED);
  EXPECT_EQ(b.core.motors[0].active_limit_ma, kRunLimit);
}

TEST(CoreHomingCurrent, AHomingLimitAboveTheRunLimitDoesNotRaiseIt) {
  HomingBoard b;
  b.params.axes[0].homing.current_limit_ma = 3 * kRunLimit;
  b.start();
  b.command(calibrate());
  for (double i : pressing_currents(b, 0, 0)) EXPECT_LE(i, kRunLimit * 1.05);
}

TEST(CoreHomingCurrent, OnTheEyeBoardVersionHoldsBothEyesToTheHomingLimit) {
  FakeBoard b(RG_COUPLING_VERSION_VERGENCE);
  b.params.axes[0].homing = rg_homing_config_t{+1, 4000.0f, 250, 20000, 4000, 10000, kHomingLimit};
  b.params.axes[1].homing = rg_homing_config_t{0, 0.0f, 0, 0, 0, 0, 0};
  b.params.axes[1].current_limit_ma = 800;  // both motors run at the lower of the two limits
  b.plant[0].counts = 1500;
  b.plant[1].counts = -2500;
  b.plant[0].stop_high = 10000;
  b.plant[1].stop_high = 10000;
  b.start();
  b.command(calibrate());
  b.run(0.3);
  EXPECT_EQ(b.core.motors[0].active_limit_ma, kHomingLimit);
  EXPECT_EQ(b.core.motors[1].active_limit_ma, kHomingLimit);
  // The left eye reaches its stop first (it starts nearer): it presses while the right one still runs.
  const auto left = pressing_currents(b, 0, 0);
  ASSERT_FALSE(left.empty());
  for (double i : left) EXPECT_LE(i, kHomingLimit * 1.05);
  b.run(8.0);
  ASSERT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_POSITION);
  EXPECT_EQ(b.core.motors[0].active_limit_ma, 800);
  EXPECT_EQ(b.core.motors[1].active_limit_ma, 800);
}

}  // namespace
}  // namespace rg_test
