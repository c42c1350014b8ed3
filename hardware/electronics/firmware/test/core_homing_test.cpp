// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Homing against a hard stop on a fake plant whose stop is somewhere the board does not know.
#include <gtest/gtest.h>

#include "fake_board.hpp"

namespace rg_test {
namespace {

std::vector<std::uint8_t> calibrate(std::int16_t pwm, std::int16_t speed_raw) {
  return {ROBOGENE_CAN_CMD_CALIBRATE_ENCODER, ROBOGENE_CAN_CALIBRATION_TYPE_HARD_STOP, static_cast<std::uint8_t>(pwm),
          static_cast<std::uint8_t>(pwm >> 8), static_cast<std::uint8_t>(speed_raw), static_cast<std::uint8_t>(speed_raw >> 8)};
}

struct HomingBoard : FakeBoard {
  HomingBoard() {
    params.axes[0].homing = rg_homing_config_t{+1, 5000.0f, 250, 15000, 1000, 5000, 0};
    plant[0].counts = 3000;          // wherever the axis was left at power-up
    plant[0].stop_high = 3000 + 7000;  // the stop, 7000 counts further on
  }
};

TEST(CoreHoming, FindsTheStopTakesItsPositionAndBacksOff) {
  HomingBoard b;
  b.start();
  EXPECT_EQ(b.core.axes[0].measured, 0) << "before homing the board counts from where it started";
  EXPECT_FALSE(b.command(calibrate(0, 0)));
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_CALIBRATION);
  b.run(0.5);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_CALIBRATION) << "still on its way at 5000 counts/s";
  EXPECT_EQ(b.command({ROBOGENE_CAN_CMD_MOTION_DONE})->data[1], 0);
  b.run(3.0);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_POSITION);
  EXPECT_EQ(b.command({ROBOGENE_CAN_CMD_MOTION_DONE})->data[1], 1);
  // The stop reads 15000 now; the axis backed off by 1000 and holds there.
  EXPECT_NEAR(b.core.axes[0].measured, 14000, 30);
  EXPECT_NEAR(b.plant[0].counts, 10000 - 1000, 30);
  EXPECT_LE(std::fabs(b.core.axes[0].output), 900);
}

TEST(CoreHoming, PushesOnlyWithTheHomingPwmAgainstTheStop) {
  HomingBoard b;
  b.start();
  b.command(calibrate(0, 0));
  int peak = 0;
  for (int t = 0; t < 3000 && b.core.axes[0].homing.phase == RG_HOMING_SEEK; ++t) {
    b.run(0.001);
    peak = std::max(peak, static_cast<int>(std::abs(b.core.axes[0].output)));
  }
  EXPECT_EQ(b.core.axes[0].homing.phase, RG_HOMING_BACKOFF);
  EXPECT_LE(peak, 250);
}

TEST(CoreHoming, HostOverridesOfPwmAndSpeedApply) {
  HomingBoard b;
  b.start();
  b.command(calibrate(120, 200));  // 120 PWM steps, 2000 counts/s
  b.run(1.0);
  EXPECT_NEAR(b.core.axes[0].speed, 2000, 300);
  EXPECT_LE(std::abs(b.core.axes[0].output), 120);
}

TEST(CoreHoming, NoStopWithinTheTimeoutLeavesTheAxisNotConfiguredAndUnpowered) {
  HomingBoard b;
  b.plant[0].stop_high.reset();
  b.start();
  b.command(calibrate(0, 0));
  b.run(4.9);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_CALIBRATION);
  b.run(0.2);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_NOT_CONFIGURED);
  EXPECT_FALSE(b.plant[0].enabled);
  EXPECT_EQ(b.core.axes[0].homing.phase, RG_HOMING_FAILED);
}

TEST(CoreHoming, AxesWithoutHomingRefuseAndKeepTheirMode) {
  HomingBoard b;
  b.start();
  b.command(calibrate(0, 0), 1);
  EXPECT_EQ(b.mode(1), ROBOGENE_CAN_CONTROL_MODE_IDLE);
}

}  // namespace
}  // namespace rg_test

namespace rg_test {
namespace {

TEST(CoreHoming, OnTheEyeBoardVersionHomesBothEyesAndFixesVergenceToo) {
  FakeBoard b(RG_COUPLING_VERSION_VERGENCE);
  b.params.axes[0].homing = rg_homing_config_t{+1, 4000.0f, 250, 20000, 4000, 10000, 0};  // version: L + R
  b.params.axes[1].homing = rg_homing_config_t{0, 0.0f, 0, 0, 0, 0, 0};              // vergence at the stops: L - R
  b.plant[0].counts = 1500;  // the eyes were left apart: the board knows neither
  b.plant[1].counts = -2500;
  b.plant[0].stop_high = 10000;
  b.plant[1].stop_high = 10000;
  b.start();
  b.command({ROBOGENE_CAN_CMD_SET_CONTROL_MODE, ROBOGENE_CAN_CONTROL_MODE_POSITION}, 1);
  b.command({ROBOGENE_CAN_CMD_CALIBRATE_ENCODER, ROBOGENE_CAN_CALIBRATION_TYPE_HARD_STOP, 0, 0, 0, 0});
  EXPECT_EQ(b.mode(1), ROBOGENE_CAN_CONTROL_MODE_IDLE) << "vergence is let go while version homes";
  b.run(8.0);
  ASSERT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_POSITION);
  EXPECT_EQ(b.mode(1), ROBOGENE_CAN_CONTROL_MODE_POSITION);
  // Both eyes went to their stops (10000 each): version read 20000 there, vergence 0; version
  // then backed off by 4000 counts, 2000 per eye.
  EXPECT_NEAR(b.plant[0].counts, 8000, 40);
  EXPECT_NEAR(b.plant[1].counts, 8000, 40);
  EXPECT_NEAR(b.core.axes[0].measured, 16000, 40);
  EXPECT_NEAR(b.core.axes[1].measured, 0, 40);
  EXPECT_NEAR(b.core.axes[0].measured, b.plant[0].counts + b.plant[1].counts, 2) << "the counts are the eyes' own now";
  EXPECT_NEAR(b.core.axes[1].measured, b.plant[0].counts - b.plant[1].counts, 2);
}

}  // namespace
}  // namespace rg_test
