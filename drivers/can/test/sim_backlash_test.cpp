// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The simulator's backlash between a motor's gear output and its joint, and a joint encoder mounted the
// other way round: the motor model's dead band (the joint follows only a flank that pushes it, friction
// holds it in the gap, the stops hold the joint), what each encoder reads, the names `robogene can-sim`
// takes, and how homing from the joint encoder meets a reversed sensor.
#include <cmath>

#include <gtest/gtest.h>

#include "board_sim_rig.hpp"
#include "robogene/can/sim/dc_motor.hpp"
#include "robogene/can/sim/motor_place.hpp"
#include "robogene/error.hpp"

namespace robogene::can {
namespace {

using sim::DcMotor;
using sim::MotorParameters;

constexpr int kYaw = 2;  // neck_yaw: board 2, axis 0
constexpr double kOneStep = 360.0 / 16384.0;

void drive_until(DcMotor& m, double duty, double output_deg) {
  for (int i = 0; i < 20000; ++i) {
    if (duty > 0 ? m.output_degrees() >= output_deg : m.output_degrees() <= output_deg) return;
    m.step(duty, 0.001);
  }
  FAIL() << "the output never reached " << output_deg;
}

TEST(SimBacklash, TheJointFollowsOnlyTheFlankThatPushesIt) {
  MotorParameters p;
  p.backlash = 1.0;
  DcMotor m(p);
  drive_until(m, 0.3, 5.0);
  EXPECT_NEAR(m.joint_degrees(), m.output_degrees() - 0.5, 1e-6) << "pushed by the upper flank, half the gap behind";
  // Turning back: the output crosses the gap, the joint stays where friction holds it.
  for (int i = 0; i < 300; ++i) m.step(0.0, 0.001);  // coast to a stop
  const double held = m.joint_degrees();
  drive_until(m, -0.2, held - 0.3);
  EXPECT_DOUBLE_EQ(m.joint_degrees(), held) << "inside the gap";
  drive_until(m, -0.2, held - 3.0);
  EXPECT_NEAR(m.joint_degrees(), m.output_degrees() + 0.5, 1e-6) << "now the lower flank drives it";
}

TEST(SimBacklash, WithoutBacklashTheJointIsTheOutput) {
  DcMotor m;
  drive_until(m, 0.3, 5.0);
  drive_until(m, -0.3, -2.0);
  EXPECT_EQ(m.joint_degrees(), m.output_degrees());
}

TEST(SimBacklash, TheStopsHoldTheJointAndTheOutputGoesOnByHalfTheGap) {
  MotorParameters p;
  p.backlash = 2.0;
  p.hard_stops = true;
  p.stop_min = -10.0;
  p.stop_max = 10.0;
  DcMotor m(p);
  for (int i = 0; i < 3000; ++i) m.step(0.5, 0.001);
  EXPECT_DOUBLE_EQ(m.joint_degrees(), 10.0);
  EXPECT_NEAR(m.output_degrees(), 11.0, 1e-9);
}

TEST(SimBacklash, TheMotorEncoderSeesTheOutputAndTheJointEncoderTheJoint) {
  HeadConfig head = testing::head_config();
  for (auto& j : head.joints) j.joint_correction_limit = 0.0;  // positions on the motor encoders: measured is the motor's
  testing::Rig rig(head);
  sim::BoardSim& board = rig.board_of(kYaw);
  board.set_backlash(0, 1.0);
  const JointConfig& yaw = rig.head.joints[kYaw];
  rig.to_joint(kYaw, SetControlMode{ControlMode::position});
  rig.to_joint(kYaw, PositionMove{static_cast<std::int32_t>(std::lround(10 * yaw.counts_per_degree)),
                                  std::round(30 * yaw.counts_per_degree / 10) * 10});
  rig.run(2.0);
  EXPECT_NEAR(rig.degrees(kYaw), board.motor_degrees(0), 1.0 / yaw.counts_per_degree) << "the motor encoder: the output";
  EXPECT_NEAR(rig.degrees(kYaw), 10.0, 0.02);
  EXPECT_LE(std::fabs(board.joint_degrees(0) - board.motor_degrees(0)), 0.5 + 1e-9) << "the joint within the gap";
  EXPECT_GT(std::fabs(board.joint_degrees(0) - board.motor_degrees(0)), 0.1) << "and not where the motor is";
  const auto r = rig.to_joint(kYaw, GetJointEncoder{});
  ASSERT_TRUE(r);
  const auto& reading = std::get<GetJointEncoderReply>(r->message);
  const double seen = ((reading.raw_angle - reading.zero + 16384) % 16384) * kOneStep;
  EXPECT_NEAR(std::remainder(seen, 360.0), board.joint_degrees(0), kOneStep) << "the joint encoder: the joint";
  EXPECT_THROW(board.set_backlash(0, -0.5), Error);
}

TEST(SimBacklash, MotorsAreNamedAsCanSimTakesThem) {
  const HeadConfig head = testing::head_config();
  const sim::MotorPlace yaw = sim::motor_place(head, "neck_yaw");
  EXPECT_EQ(yaw.board, 2);
  EXPECT_EQ(yaw.motor, 0);
  const sim::MotorPlace right = sim::motor_place(head, "right_eye_pan");
  EXPECT_EQ(right.board, 3);
  EXPECT_EQ(right.motor, 1);
  try {
    sim::motor_place(head, "eyes_version");
    FAIL() << "a coupled joint is no motor";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("left_eye_pan"), std::string::npos) << e.what();
  }
}

// Homing takes the reversed sensor's angle as it comes: at the joint's 0, where the lab measured its zero,
// it reads right; anywhere else it reads the mirror angle, and nothing at power-up can tell.
TEST(SimBacklash, HomingFromAReversedEncoderTakesTheMirrorAngle) {
  testing::Rig rig;
  sim::BoardSim& board = rig.board_of(kYaw);
  board.set_joint_encoder_reversed(0, true);
  board.power_up_at(0.0, 0.0);
  rig.run(0.01);
  EXPECT_NEAR(rig.degrees(kYaw), 0.0, kOneStep);
  board.power_up_at(12.0, 0.0);
  rig.run(0.01);
  EXPECT_EQ(board.mode(0), ControlMode::idle) << "homed";
  EXPECT_NEAR(rig.degrees(kYaw), -12.0, kOneStep) << "the joint at +12 deg homes at -12";
}

}  // namespace
}  // namespace robogene::can
