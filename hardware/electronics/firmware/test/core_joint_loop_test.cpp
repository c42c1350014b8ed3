// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The joint loop (rg_joint_loop.h): an axis with a joint encoder and a correction limit closes its position on
// the joint, through a gear with backlash between the motor and the joint. It ends within two counts of the
// encoder on either side of the gap and stays there (no limit cycle); it reports the joint's position; a reversed
// encoder runs the correction away and stops the axis with joint_encoder_mismatch; an encoder that fails while
// running leaves the axis on its motor encoder, reported, not stopped.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fake_board.hpp"
#include "rg_joint_encoder.h"
#include "rg_joint_loop.h"
#include "rg_wire.h"

namespace rg_test {
namespace {

constexpr double kCountsPerDegree = 100.0;
constexpr double kStep = 360.0 / 16384.0;  // one count of the AS5048A, deg
constexpr double kLimitDegrees = 3.0;

// Axis 0 drives its joint through `backlash` degrees of play; its AS5048A reads the joint.
struct BacklashBoard : FakeBoard {
  double backlash = 1.0;   // deg
  double joint = 0.0;      // deg, the joint beyond the gap
  bool reversed = false;   // the sensor counts down as the joint turns up
  bool flip_parity = false;
  std::uint16_t magnet = 5000;

  explicit BacklashBoard(double limit_degrees = kLimitDegrees) {
    auto& a = params.axes[0];
    a.joint_encoder_bits = 14;
    a.counts_per_degree = static_cast<float>(kCountsPerDegree);
    a.min_position = -3000;
    a.max_position = 3000;
    a.joint_zero = magnet;
    a.joint_zero_stored = true;
    a.joint_correction_limit = static_cast<std::int32_t>(std::lround(limit_degrees * kCountsPerDegree));
    joint_frames = [this](unsigned) -> std::uint16_t {
      follow_output();
      const long steps = std::lround((reversed ? -joint : joint) / kStep) + magnet;
      const auto raw = static_cast<std::uint16_t>(((steps % 16384) + 16384) % 16384);
      const std::uint16_t frame = rg_as5048a_frame(raw, false);
      return flip_parity ? static_cast<std::uint16_t>(frame ^ 0x0001u) : frame;
    };
  }
  double output() const { return plant[0].counts / kCountsPerDegree; }
  // The joint moves only when a flank of the gap pushes it; friction holds it in between.
  void follow_output() {
    const double half = 0.5 * backlash;
    joint = std::clamp(joint, output() - half, output() + half);
  }
  void set_mode(std::uint8_t mode) { command({ROBOGENE_CAN_CMD_SET_CONTROL_MODE, mode}); }
  void move_to(double degrees) {
    command(position_move(static_cast<std::int32_t>(std::lround(degrees * kCountsPerDegree)), 2000));  // 20 deg/s
  }
  const rg_axis_t& axis() const { return core.axes[0]; }
};

TEST(CoreJointLoop, TakesUpTheBacklashOnEitherSideOfTheGap) {
  BacklashBoard b;
  b.start();
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_POSITION);
  for (const double target : {10.0, 0.0, -10.0, 5.0}) {
    b.move_to(target);
    b.run(2.0);
    EXPECT_NEAR(b.joint, target, 2 * kStep) << "moving to " << target;
    EXPECT_GT(std::fabs(b.output() - target), 0.4) << "the motor sits half the gap beyond";
  }
  EXPECT_EQ(b.axis().faults, 0);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_POSITION);
}

// The same head without the joint loop (no correction limit: today's motor-encoder loop): the motor ends on the
// target, the joint half the gap off it, on the flank the motor last pushed.
TEST(CoreJointLoop, OnTheMotorEncoderAloneTheJointStopsHalfTheGapOff) {
  BacklashBoard b(0.0);
  b.start();
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_POSITION);
  for (const double target : {10.0, 0.0}) {
    b.move_to(target);
    b.run(2.0);
    EXPECT_NEAR(b.output(), target, 0.02) << "the motor on its target";
    EXPECT_NEAR(std::fabs(b.joint - target), 0.5, 2 * kStep) << "the joint on a flank, half the gap off";
  }
}

TEST(CoreJointLoop, SettlesWithoutALimitCycle) {
  BacklashBoard b;
  b.start();
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.move_to(10.0);
  b.run(2.0);
  b.move_to(0.0);
  b.run(2.0);
  double joint_lo = 1e9, joint_hi = -1e9, out_lo = 1e9, out_hi = -1e9;
  int pwm_lo = 100000, pwm_hi = -100000;
  float correction_lo = 1e9f, correction_hi = -1e9f;
  for (int i = 0; i < 1000; ++i) {  // one second, every period
    b.run(0.001);
    joint_lo = std::min(joint_lo, b.joint), joint_hi = std::max(joint_hi, b.joint);
    out_lo = std::min(out_lo, b.output()), out_hi = std::max(out_hi, b.output());
    pwm_lo = std::min<int>(pwm_lo, b.axis().output), pwm_hi = std::max<int>(pwm_hi, b.axis().output);
    correction_lo = std::min(correction_lo, b.axis().joint_correction);
    correction_hi = std::max(correction_hi, b.axis().joint_correction);
  }
  EXPECT_NEAR(joint_lo, 0.0, 2 * kStep);
  EXPECT_NEAR(joint_hi, 0.0, 2 * kStep);
  EXPECT_LT(joint_hi - joint_lo, kStep) << "the joint stays put";
  EXPECT_LT(out_hi - out_lo, 0.05) << "the motor does not cross the gap back and forth";
  EXPECT_EQ(correction_hi, correction_lo) << "the correction rests inside the dead band";
  // What is left is the motor loop's own dither of a count or two about its reference: (kp + kd) >> shift is about
  // 4 PWM steps a count.
  EXPECT_LE(std::max(pwm_hi, -pwm_lo), 13) << "the drive is steady";
}

TEST(CoreJointLoop, VelocityModeSettlesOnTheJointToo) {
  BacklashBoard b;
  b.start();
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_VELOCITY);
  const auto velocity = [&](std::int16_t raw) {
    b.command({ROBOGENE_CAN_CMD_VELOCITY_MOVE, static_cast<std::uint8_t>(raw), static_cast<std::uint8_t>(raw >> 8), 0, 0});
  };
  for (int i = 0; i < 40; ++i) {  // 10 deg/s for 0.4 s, refreshed within the host timeout
    velocity(100);
    b.run(0.01);
  }
  for (int i = 0; i < 40; ++i) {  // and back at 10 deg/s
    velocity(-100);
    b.run(0.01);
  }
  velocity(0);
  b.run(1.5);
  EXPECT_NEAR(b.joint, b.axis().traj.ref / kCountsPerDegree, 2 * kStep) << "the joint where the reference stopped";
  EXPECT_GT(std::fabs(b.output() - b.joint), 0.4) << "the motor holds the far flank";
}

TEST(CoreJointLoop, ReportsTheJointsPositionNotTheMotors) {
  BacklashBoard b;
  b.start();
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.move_to(10.0);
  b.run(2.0);
  const auto r = b.command({ROBOGENE_CAN_CMD_GET_ENCODER_POSITION});
  ASSERT_TRUE(r);
  EXPECT_NEAR(rg_get_i32(r->data + 1) / kCountsPerDegree, b.joint, kStep);
  EXPECT_GT(std::fabs(rg_get_i32(r->data + 1) / kCountsPerDegree - b.output()), 0.4);
  // set_encoder_position would only shift the motor's counts away from the joint's: ignored.
  b.command(le32(ROBOGENE_CAN_CMD_SET_ENCODER_POSITION, 0));
  b.run(0.1);
  EXPECT_NEAR(b.axis().measured / kCountsPerDegree, 10.0, 2 * kStep);
  EXPECT_EQ(b.axis().faults, 0);
}

TEST(CoreJointLoop, AReversedEncoderRunsTheCorrectionAwayAndStopsTheAxis) {
  BacklashBoard b;
  b.reversed = true;  // homes right at 0 deg, where its zero was measured
  b.start();
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_IDLE);
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.move_to(10.0);
  float correction = 0.0f;  // the last one the motor loop ran with
  for (int i = 0; i < 3000 && b.mode(0) == ROBOGENE_CAN_CONTROL_MODE_POSITION; ++i) {
    correction = b.axis().joint_correction;
    b.run(0.001);
  }
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT);
  EXPECT_TRUE(b.axis().faults & ROBOGENE_CAN_AXIS_FAULTS_JOINT_ENCODER_MISMATCH);
  EXPECT_FALSE(b.plant[0].enabled) << "the bridge is off";
  // The motor was taken beyond where its own loop would hold it by the limit and one period's step at most.
  EXPECT_GT(correction / kCountsPerDegree, kLimitDegrees - 0.05);
  EXPECT_LE(correction / kCountsPerDegree, kLimitDegrees + RG_JOINT_LOOP_MAX_RATE_DEG_S * 0.001 + 1e-3);
  const double stopped_at = b.joint;
  b.run(1.0);
  EXPECT_NEAR(b.joint, stopped_at, 0.5) << "it stopped";
  // force_idle clears the latch, but the mismatch is still there: the next run faults again at once.
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_FORCE_IDLE);
  b.run(0.01);
  EXPECT_TRUE(b.axis().faults & ROBOGENE_CAN_AXIS_FAULTS_JOINT_ENCODER_MISMATCH) << "reported while idle";
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.run(0.01);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT);
}

TEST(CoreJointLoop, AnEncoderFailingWhileRunningLeavesTheAxisOnItsMotorEncoder) {
  BacklashBoard b;
  b.start();
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.move_to(10.0);
  b.run(2.0);
  const std::int32_t before = b.axis().measured;
  b.flip_parity = true;
  b.run(0.01);
  EXPECT_TRUE(b.axis().faults & ROBOGENE_CAN_AXIS_FAULTS_ABSOLUTE_ENCODER_ERROR);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_POSITION) << "not stopped";
  EXPECT_NEAR(b.axis().measured, before, 2 * kStep * kCountsPerDegree) << "the reported position does not jump";
  // It still moves, on its motor encoder with the correction it had: the backlash is no longer taken up.
  b.move_to(0.0);
  b.run(2.0);
  EXPECT_NEAR(b.axis().measured / kCountsPerDegree, 0.0, 2 * kStep);
  // The motor holds where the frozen correction puts it (half a gap off, the flank the joint last needed); the joint
  // may rest on either flank from there: within the whole gap of its target, no longer taken up.
  EXPECT_LE(std::fabs(b.joint), b.backlash + kStep);
  EXPECT_EQ(b.axis().faults & ROBOGENE_CAN_AXIS_FAULTS_JOINT_ENCODER_MISMATCH, 0);
  // The sensor back: the joint loop takes the joint onto its target again.
  b.flip_parity = false;
  b.run(2.0);
  EXPECT_EQ(b.axis().faults, 0);
  EXPECT_NEAR(b.joint, 0.0, 2 * kStep);
}

}  // namespace
}  // namespace rg_test
