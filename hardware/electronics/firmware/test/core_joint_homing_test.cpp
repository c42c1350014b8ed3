// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Homing from the absolute joint encoder: a joint powered up at an angle the motor encoder cannot know
// takes its position from its AS5048A and the stored zero; a missing or failing encoder, or no zero,
// leaves it not_configured, refusing to run, with the fault in its status.
#include <gtest/gtest.h>

#include <cmath>

#include "fake_board.hpp"
#include "rg_joint_encoder.h"
#include "rg_wire.h"

namespace rg_test {
namespace {

constexpr double kCountsPerDegree = 100.0;

// Axis 0 has a joint encoder (14 bits) on a joint with limits -30..22 deg; axis 1 has none.
struct JointBoard : FakeBoard {
  double power_up_degrees = 12.5;  // where the joint is when the board starts
  std::uint16_t magnet = 9000;     // the raw angle the sensor reads at the joint's 0 deg
  bool error_flag = false, flip_parity = false;

  JointBoard() {
    auto& a = params.axes[0];
    a.joint_encoder_bits = 14;
    a.counts_per_degree = static_cast<float>(kCountsPerDegree);
    a.min_position = -3000;
    a.max_position = 2200;
    a.joint_zero = magnet;
    a.joint_zero_stored = true;
    params.axes[1].counts_per_degree = static_cast<float>(kCountsPerDegree);
    joint_frames = [this](unsigned axis) -> std::uint16_t {
      EXPECT_EQ(axis, 0u) << "only an axis with a joint encoder is read";
      const double degrees = power_up_degrees + plant[0].counts / kCountsPerDegree;
      const long steps = std::lround(degrees * 16384.0 / 360.0) + magnet;
      const auto raw = static_cast<std::uint16_t>(((steps % 16384) + 16384) % 16384);
      const std::uint16_t frame = rg_as5048a_frame(raw, error_flag);
      return flip_parity ? static_cast<std::uint16_t>(frame ^ 0x0001u) : frame;
    };
  }
  double joint_degrees() const { return power_up_degrees + plant[0].counts / kCountsPerDegree; }
  std::optional<rg_can_frame_t> set_mode(std::uint8_t mode, unsigned axis = 0) {
    return command({ROBOGENE_CAN_CMD_SET_CONTROL_MODE, mode}, axis);
  }
  rg_can_frame_t joint_encoder_reply(unsigned axis = 0) { return *command({ROBOGENE_CAN_CMD_GET_JOINT_ENCODER}, axis); }
  void set_zero(std::uint16_t zero, unsigned axis = 0) {
    command({ROBOGENE_CAN_CMD_SET_JOINT_ENCODER_ZERO, static_cast<std::uint8_t>(zero), static_cast<std::uint8_t>(zero >> 8)},
            axis);
  }
};

constexpr double kCountsPerStep = kCountsPerDegree * 360.0 / 16384.0;  // one LSB of the sensor, in counts

TEST(CoreJointHoming, TakesThePositionFromTheJointEncoderAtPowerUp) {
  JointBoard b;
  b.start();
  EXPECT_EQ(b.joint_frames_read[0], static_cast<int>(RG_JOINT_ENCODER_STARTUP_FRAMES));
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_IDLE) << "homed before the first control period";
  EXPECT_NEAR(b.core.axes[0].measured, 12.5 * kCountsPerDegree, kCountsPerStep);
  // It now runs, and its 0 is the joint's 0.
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.command(position_move(0, 2000));
  b.run(2.0);
  EXPECT_NEAR(b.joint_degrees(), 0.0, 0.1);
  EXPECT_EQ(b.core.axes[0].faults, 0);
}

TEST(CoreJointHoming, WrapsIntoTheJointsRange) {
  JointBoard b;
  b.power_up_degrees = -27.0;
  b.magnet = 200;  // raw 200 - 1229 wraps below 0: the sensor reads about 15355
  b.params.axes[0].joint_zero = 200;
  b.start();
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_IDLE);
  EXPECT_NEAR(b.core.axes[0].measured, -27.0 * kCountsPerDegree, kCountsPerStep);
}

TEST(CoreJointHoming, ReadsOneFramePerPeriodAndOnlyWhereThereIsAnEncoder) {
  JointBoard b;
  b.start();
  b.run(0.010);
  EXPECT_EQ(b.joint_frames_read[0], static_cast<int>(RG_JOINT_ENCODER_STARTUP_FRAMES) + 10);
  EXPECT_EQ(b.joint_frames_read[1], 0);
}

void expect_refuses_to_run(JointBoard& b) {
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_NOT_CONFIGURED);
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_POSITION);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_NOT_CONFIGURED) << "no position mode on an unknown zero";
  b.command(position_move(1000, 2000));
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_VELOCITY);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_NOT_CONFIGURED);
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_FORCE_IDLE);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_NOT_CONFIGURED) << "force_idle does not home it either";
  b.run(0.5);
  EXPECT_FALSE(b.plant[0].enabled) << "the bridge stays off";
  EXPECT_DOUBLE_EQ(b.plant[0].counts, 0.0);
  // The axis without a joint encoder is not held back.
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_POSITION, 1);
  EXPECT_EQ(b.mode(1), ROBOGENE_CAN_CONTROL_MODE_POSITION);
}

std::uint8_t status_faults0(JointBoard& b) {
  b.params.broadcast_policy = 0;
  b.core.policy = ROBOGENE_CAN_BROADCAST_MASK_STATUS;
  b.sent.clear();
  b.core.sent_once[2] = false;  // the status slot: send now
  rg_board_tick(&b.core);
  for (const auto& f : b.sent) {
    if (f.id == ROBOGENE_CAN_ID(ROBOGENE_CAN_CLASS_PERIODIC_MOTOR_CONTROL, 1, ROBOGENE_CAN_BCAST_STATUS)) {
      return f.data[ROBOGENE_CAN_STATUS_BROADCAST_FAULTS0_BYTE];
    }
  }
  ADD_FAILURE() << "no status broadcast";
  return 0;
}

TEST(CoreJointHoming, AMissingEncoderLeavesTheAxisUnhomedWithAFault) {
  JointBoard b;
  b.joint_frames = nullptr;  // the data line's pull-down: 0x0000 on every frame
  b.start();
  expect_refuses_to_run(b);
  EXPECT_EQ(status_faults0(b) & ROBOGENE_CAN_AXIS_FAULTS_ABSOLUTE_ENCODER_ERROR, ROBOGENE_CAN_AXIS_FAULTS_ABSOLUTE_ENCODER_ERROR);
  const rg_can_frame_t r = b.joint_encoder_reply();
  EXPECT_EQ(r.len, ROBOGENE_CAN_LEN_GET_JOINT_ENCODER_REPLY);
  EXPECT_EQ(r.data[ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_STATE_BYTE], ROBOGENE_CAN_JOINT_ENCODER_STATE_ABSENT);
  EXPECT_EQ(r.data[ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_HOMED_BYTE], 0);
}

TEST(CoreJointHoming, BadParityLeavesTheAxisUnhomedWithAFault) {
  JointBoard b;
  b.flip_parity = true;
  b.start();
  expect_refuses_to_run(b);
  EXPECT_NE(status_faults0(b) & ROBOGENE_CAN_AXIS_FAULTS_ABSOLUTE_ENCODER_ERROR, 0);
  EXPECT_EQ(b.joint_encoder_reply().data[ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_STATE_BYTE],
            ROBOGENE_CAN_JOINT_ENCODER_STATE_FAILED);
}

TEST(CoreJointHoming, TheSensorsErrorFlagLeavesTheAxisUnhomed) {
  JointBoard b;
  b.error_flag = true;
  b.start();
  expect_refuses_to_run(b);
  EXPECT_NE(status_faults0(b) & ROBOGENE_CAN_AXIS_FAULTS_ABSOLUTE_ENCODER_ERROR, 0);
}

TEST(CoreJointHoming, AnAngleFarOutsideTheJointsRangeIsNotTaken) {
  JointBoard b;
  b.params.axes[0].joint_zero = static_cast<std::uint16_t>(b.magnet + 4096);  // a zero 90 deg off: a slipped magnet
  b.start();
  expect_refuses_to_run(b);
  EXPECT_NE(status_faults0(b) & ROBOGENE_CAN_AXIS_FAULTS_ABSOLUTE_ENCODER_ERROR, 0);
}

TEST(CoreJointHoming, NoStoredZeroWaitsForOneAndTheStoredZeroHomes) {
  JointBoard b;
  b.params.axes[0].joint_zero_stored = false;
  b.params.axes[0].joint_zero = 0;
  b.start();
  expect_refuses_to_run(b);
  rg_can_frame_t r = b.joint_encoder_reply();
  EXPECT_EQ(r.data[ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_STATE_BYTE], ROBOGENE_CAN_JOINT_ENCODER_STATE_OK);
  EXPECT_EQ(r.data[ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_ZERO_STORED_BYTE], 0);
  // The lab reads the raw angle with the joint at its 0 (here 12.5 deg from it) and stores the zero.
  const std::uint16_t raw = rg_get_u16(r.data + ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_RAW_ANGLE_BYTE);
  EXPECT_NEAR(raw, b.magnet + 12.5 * 16384.0 / 360.0, 1.0);
  b.set_zero(b.magnet);
  ASSERT_EQ(b.saved_zeros.size(), 1u);
  EXPECT_EQ(b.saved_zeros[0], std::make_pair(0u, b.magnet));
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_IDLE);
  EXPECT_NEAR(b.core.axes[0].measured, 12.5 * kCountsPerDegree, kCountsPerStep);
  r = b.joint_encoder_reply();
  EXPECT_EQ(rg_get_u16(r.data + ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_ZERO_BYTE), b.magnet);
  EXPECT_EQ(r.data[ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_ZERO_STORED_BYTE], 1);
  EXPECT_EQ(r.data[ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_HOMED_BYTE], 1);
}

TEST(CoreJointHoming, AZeroIsRefusedWhileRunningBeyondTheBitsOrWithoutAnEncoder) {
  JointBoard b;
  b.start();
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.set_zero(100);
  b.set_zero(100, 1);
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_IDLE);
  b.set_zero(16384);
  EXPECT_TRUE(b.saved_zeros.empty());
  EXPECT_EQ(b.params.axes[0].joint_zero, 9000) << "the start-up copy";
  EXPECT_EQ(b.core.params.axes[0].joint_zero, 9000);
  EXPECT_EQ(b.joint_encoder_reply(1).data[ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_STATE_BYTE],
            ROBOGENE_CAN_JOINT_ENCODER_STATE_NONE);
}

TEST(CoreJointHoming, AnEncoderLostAfterHomingIsReportedButDoesNotStopTheAxis) {
  JointBoard b;
  b.start();
  b.set_mode(ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.run(0.1);
  b.flip_parity = true;
  b.run(0.1);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_POSITION) << "its loop runs on the motor encoder";
  EXPECT_NE(status_faults0(b) & ROBOGENE_CAN_AXIS_FAULTS_ABSOLUTE_ENCODER_ERROR, 0);
}

}  // namespace
}  // namespace rg_test

namespace rg_test {
namespace {

constexpr double kPanCounts = 100.0;  // each eye motor's counts per degree of its pan

// The eye board with an AS5048A per pan (codegen gives version and vergence encoder bits only when both pans
// have one): encoder 0 is the left pan's, beside motor 0; version = (L + R) / 2, vergence = L - R.
struct EyeBoard : FakeBoard {
  double left0 = 10.0, right0 = 4.0;  // the pans' angles at power-up
  std::uint16_t magnet[2] = {3000, 12000};
  bool missing_right = false;

  EyeBoard() : FakeBoard(RG_COUPLING_VERSION_VERGENCE) {
    auto& v = params.axes[0];
    auto& g = params.axes[1];
    v.counts_per_degree = static_cast<float>(2.0 * kPanCounts);  // version travels as L + R motor counts
    g.counts_per_degree = static_cast<float>(kPanCounts);        // vergence as L - R
    v.min_position = -6000;
    v.max_position = 6000;
    g.min_position = 0;
    g.max_position = 4500;
    for (unsigned i = 0; i < 2; ++i) {
      params.axes[i].joint_encoder_bits = 14;
      params.axes[i].joint_zero = magnet[i];
      params.axes[i].joint_zero_stored = true;
    }
    joint_frames = [this](unsigned encoder) -> std::uint16_t {
      if (encoder == 1 && missing_right) return 0;
      const long steps = std::lround(pan(encoder) * 16384.0 / 360.0) + magnet[encoder];
      return rg_as5048a_frame(static_cast<std::uint16_t>(((steps % 16384) + 16384) % 16384), false);
    };
  }
  double pan(unsigned i) const { return (i == 0 ? left0 : right0) + plant[i].counts / kPanCounts; }
};

TEST(CoreJointHoming, TheEyeBoardDerivesVersionAndVergenceFromBothPans) {
  EyeBoard b;
  b.start();
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_IDLE);
  EXPECT_EQ(b.mode(1), ROBOGENE_CAN_CONTROL_MODE_IDLE);
  const double step = 360.0 / 16384.0;
  EXPECT_NEAR(b.core.axes[0].measured / (2.0 * kPanCounts), 7.0, step) << "version = (10 + 4) / 2";
  EXPECT_NEAR(b.core.axes[1].measured / kPanCounts, 6.0, 2 * step) << "vergence = 10 - 4";
  // Both run, and 0 version with 0 vergence is both eyes straight ahead.
  b.command({ROBOGENE_CAN_CMD_SET_CONTROL_MODE, ROBOGENE_CAN_CONTROL_MODE_POSITION}, 0);
  b.command({ROBOGENE_CAN_CMD_SET_CONTROL_MODE, ROBOGENE_CAN_CONTROL_MODE_POSITION}, 1);
  b.command(position_move(0, 2000), 0);
  b.command(position_move(0, 2000), 1);
  b.run(3.0);
  EXPECT_NEAR(b.pan(0), 0.0, 0.15);
  EXPECT_NEAR(b.pan(1), 0.0, 0.15);
}

TEST(CoreJointHoming, AnAxisWithAJointEncoderIsNeverRunIntoAStop) {
  EyeBoard b;
  b.missing_right = true;  // unhomed
  b.params.axes[0].homing = rg_homing_config_t{+1, 5000.0f, 250, 15000, 1000, 5000, 0};
  b.start();
  b.command({ROBOGENE_CAN_CMD_CALIBRATE_ENCODER, ROBOGENE_CAN_CALIBRATION_TYPE_HARD_STOP, 0, 0, 0, 0}, 0);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_NOT_CONFIGURED);
  b.run(0.2);
  EXPECT_FALSE(b.plant[0].enabled);
}

TEST(CoreJointHoming, OnePansMissingEncoderLeavesBothEyeJointsUnhomed) {
  EyeBoard b;
  b.missing_right = true;
  b.start();
  for (unsigned axis = 0; axis < 2; ++axis) {
    EXPECT_EQ(b.mode(axis), ROBOGENE_CAN_CONTROL_MODE_NOT_CONFIGURED) << axis;
    b.command({ROBOGENE_CAN_CMD_SET_CONTROL_MODE, ROBOGENE_CAN_CONTROL_MODE_POSITION}, axis);
    EXPECT_EQ(b.mode(axis), ROBOGENE_CAN_CONTROL_MODE_NOT_CONFIGURED) << axis;
  }
  b.run(0.01);
  EXPECT_NE(b.core.axes[0].faults & ROBOGENE_CAN_AXIS_FAULTS_ABSOLUTE_ENCODER_ERROR, 0) << "version needs the right pan too";
  EXPECT_NE(b.core.axes[1].faults & ROBOGENE_CAN_AXIS_FAULTS_ABSOLUTE_ENCODER_ERROR, 0);
  // The encoder plugged back in: both home together.
  b.missing_right = false;
  b.run(0.02);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_IDLE);
  EXPECT_EQ(b.mode(1), ROBOGENE_CAN_CONTROL_MODE_IDLE);
  EXPECT_NEAR(b.core.axes[1].measured / kPanCounts, 6.0, 0.05);
}

}  // namespace
}  // namespace rg_test
