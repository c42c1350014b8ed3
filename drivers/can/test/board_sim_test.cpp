// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The simulated boards stepped by hand (no bus, no wall clock): the firmware's behaviour and the
// motor model, deterministic.
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "board_sim_rig.hpp"

namespace robogene::can::sim {
namespace {

using testing::Rig;

TEST(BoardSim, EveryJointFollowsAPositionMoveAndSettlesOnTheTarget) {
  Rig rig;
  for (int j = 0; j < 6; ++j) {
    const JointConfig& jc = rig.head.joints[static_cast<std::size_t>(j)];
    rig.to_joint(j, SetControlMode{ControlMode::position});
    const double target = jc.min + 0.75 * (jc.max - jc.min);
    rig.to_joint(j, SetDesiredAcceleration{std::round(100 * jc.counts_per_degree / 1000) * 1000});
    rig.to_joint(j, PositionMove{static_cast<std::int32_t>(std::lround(target * jc.counts_per_degree)),
                                 std::round(20 * jc.counts_per_degree / 10) * 10});
    auto done = rig.to_joint(j, MotionDone{});
    ASSERT_TRUE(done);
    EXPECT_FALSE(std::get<MotionDoneReply>(done->message).done) << jc.name;
    // Halfway through the move (20 deg/s) the joint is on its way, close behind the trajectory.
    rig.run(std::fabs(target) / 20.0 / 2.0);
    const double mid = rig.degrees(j);
    EXPECT_GT(std::fabs(mid), 0.2 * std::fabs(target)) << jc.name;
    EXPECT_LT(std::fabs(mid), 0.8 * std::fabs(target)) << jc.name;
    rig.run(std::fabs(target) / 20.0 / 2.0 + 1.5);
    EXPECT_NEAR(rig.degrees(j), target, 0.1) << jc.name;
    EXPECT_TRUE(std::get<MotionDoneReply>(rig.to_joint(j, MotionDone{})->message).done) << jc.name;
  }
}

TEST(BoardSim, VelocityMovesAreFollowedAndStopWhenTheHostFallsSilent) {
  Rig rig;
  for (int j = 0; j < 6; ++j) {
    const JointConfig& jc = rig.head.joints[static_cast<std::size_t>(j)];
    rig.to_joint(j, SetControlMode{ControlMode::velocity});
    const double start = rig.degrees(j);
    const double speed = 10.0;  // deg/s
    const auto counts_speed = std::round(speed * jc.counts_per_degree / 10) * 10;
    const auto counts_acc = std::round(200 * jc.counts_per_degree / 1000) * 1000;
    for (int k = 0; k < 50; ++k) {  // refreshed every 20 ms for 1 s, as the driver does
      rig.to_joint(j, VelocityMove{counts_speed, counts_acc});
      rig.run(0.02);
    }
    EXPECT_NEAR(rig.degrees(j) - start, speed * (1.0 - 0.025), 0.6) << jc.name;
    const double at_silence = rig.degrees(j);
    rig.run(1.0);  // no refresh: the board's 100 ms velocity timeout stops the joint
    EXPECT_LT(std::fabs(rig.degrees(j) - at_silence), 2.0) << jc.name;
    const double stopped = rig.degrees(j);
    rig.run(0.5);
    EXPECT_NEAR(rig.degrees(j), stopped, 0.05) << jc.name;
  }
}

TEST(BoardSim, EyeBoardMixesVersionAndVergenceIntoTheTwoEyeMotors) {
  Rig rig;
  const int version = 4, vergence = 5;
  rig.to_joint(version, SetControlMode{ControlMode::position});
  rig.to_joint(vergence, SetControlMode{ControlMode::position});
  auto move = [&](int j, double deg) {
    const JointConfig& jc = rig.head.joints[static_cast<std::size_t>(j)];
    rig.to_joint(j, PositionMove{static_cast<std::int32_t>(std::lround(deg * jc.counts_per_degree)),
                                 std::round(40 * jc.counts_per_degree / 10) * 10});
  };
  move(version, 10.0);
  move(vergence, 20.0);
  rig.run(3.0);
  BoardSim& eyes = rig.board_of(version);
  // left = version + vergence / 2, right = version - vergence / 2 (the config's j2m)
  EXPECT_NEAR(eyes.motor_degrees(0), 20.0, 0.1);
  EXPECT_NEAR(eyes.motor_degrees(1), 0.0, 0.1);
  EXPECT_NEAR(rig.degrees(version), 10.0, 0.1);
  EXPECT_NEAR(rig.degrees(vergence), 20.0, 0.1);
}

TEST(BoardSim, BroadcastsFollowThePolicyAndTheirPeriods) {
  Rig rig;
  rig.run(1.0);
  std::map<std::pair<int, std::string>, int> counts;
  for (const auto& e : rig.broadcasts) ++counts[{e.source, message_name(e.message)}];
  for (const auto& b : rig.head.boards) {
    EXPECT_EQ((counts[{b.address, "position_broadcast"}]), 200) << b.name;
    EXPECT_EQ((counts[{b.address, "velocity_broadcast"}]), 100) << b.name;
    EXPECT_EQ((counts[{b.address, "current_broadcast"}]), 100) << b.name;
    EXPECT_EQ((counts[{b.address, "supply_broadcast"}]), 1) << b.name;
    EXPECT_EQ((counts[{b.address, "status_broadcast"}]), 1) << b.name;  // sent at start, then on change
    EXPECT_EQ((counts[{b.address, "pid_output_broadcast"}]), 0) << b.name;
  }
}

TEST(BoardSim, RepliesWithFirmwareVersionAndCompatibility) {
  Rig rig;
  auto r = rig.send(1, 0, GetFirmwareVersion{static_cast<std::uint8_t>(rig.head.protocol_major),
                                             static_cast<std::uint8_t>(rig.head.protocol_minor)});
  ASSERT_TRUE(r);
  const auto& v = std::get<GetFirmwareVersionReply>(r->message);
  EXPECT_EQ(v.board_type, BoardType::robogene_motor_board);
  EXPECT_TRUE(v.compatible);
  EXPECT_EQ(r->source, 1);
  EXPECT_EQ(r->destination, kHostAddress);
  auto newer = rig.send(1, 0, GetFirmwareVersion{static_cast<std::uint8_t>(rig.head.protocol_major + 1), 0});
  EXPECT_FALSE(std::get<GetFirmwareVersionReply>(newer->message).compatible);
}

TEST(BoardSim, PositionMovesAreIgnoredOutsidePositionModeAndClampedToLimits) {
  Rig rig;
  const JointConfig& pitch = rig.head.joints[0];
  rig.to_joint(0, PositionMove{static_cast<std::int32_t>(10 * pitch.counts_per_degree), 2000});
  rig.run(1.0);
  EXPECT_NEAR(rig.degrees(0), 0.0, 0.01) << "idle axis moved";
  rig.to_joint(0, SetControlMode{ControlMode::position});
  rig.to_joint(0, PositionMove{static_cast<std::int32_t>(100 * pitch.counts_per_degree),
                               std::round(100 * pitch.counts_per_degree / 10) * 10});
  rig.run(2.0);
  EXPECT_NEAR(rig.degrees(0), pitch.max, 0.1);
}

TEST(BoardSim, EyesHomeAgainstTheirHardStopsFromWhereverTheyPoweredUp) {
  Rig rig;
  const int version = 4, vergence = 5;
  const JointConfig& v = rig.head.joints[version];
  const JointConfig& g = rig.head.joints[vergence];
  ASSERT_EQ(v.homing.direction, 1) << "the parameter file homes version towards the upper stops";
  BoardSim& eyes = rig.board_of(version);
  eyes.power_up_at(12.0, -7.0);  // the eyes were left apart; the board counts from 0 here
  EXPECT_NEAR(rig.degrees(version), 0.0, 0.01);
  rig.to_joint(version, CalibrateEncoder{CalibrationType::hard_stop, 0, 0});
  EXPECT_EQ(eyes.mode(0), ControlMode::calibration);
  const double travel = v.homing.stop - 12.0 + 19.0;  // the right eye has further to go
  rig.run(travel / v.homing.speed + 0.5 + v.homing.backoff / v.homing.speed + 1.0);
  ASSERT_EQ(eyes.mode(0), ControlMode::position);
  EXPECT_EQ(eyes.mode(1), ControlMode::position);
  // What the board reports is now where the eyes are.
  const double left = eyes.motor_degrees(0), right = eyes.motor_degrees(1);
  EXPECT_NEAR(rig.degrees(version), (left + right) / 2, 0.05);
  EXPECT_NEAR(rig.degrees(vergence), left - right, 0.05);
  EXPECT_NEAR(rig.degrees(version), v.homing.stop - v.homing.backoff, 0.2);
  EXPECT_NEAR(rig.degrees(vergence), g.homing.stop, 0.2);
  // And a move lands where asked, in the eyes' true angles.
  rig.to_joint(version, PositionMove{static_cast<std::int32_t>(std::lround(5.0 * v.counts_per_degree)),
                                     std::round(40 * v.counts_per_degree / 10) * 10});
  rig.run(2.0);
  EXPECT_NEAR(eyes.motor_degrees(0), 5.0, 0.1);
  EXPECT_NEAR(eyes.motor_degrees(1), 5.0, 0.1);
}

TEST(BoardSim, JointsWithoutHomingRefuseToCalibrate) {
  Rig rig;
  rig.to_joint(0, CalibrateEncoder{CalibrationType::hard_stop, 0, 0});
  EXPECT_EQ(rig.board_of(0).mode(0), ControlMode::idle);
}

TEST(BoardSim, ALowSupplyStopsARunningJointWithAFaultTheStatusReports) {
  Rig rig;
  rig.to_joint(0, SetControlMode{ControlMode::position});
  rig.run(0.1);
  rig.board_of(0).set_supply_voltage(7.5);
  rig.broadcasts.clear();
  rig.run(0.01);
  EXPECT_EQ(rig.board_of(0).mode(0), ControlMode::hardware_fault);
  bool reported = false;
  for (const auto& e : rig.broadcasts) {
    if (const auto* st = std::get_if<StatusBroadcast>(&e.message); st && e.source == 1) {
      reported = st->mode0 == ControlMode::hardware_fault && (st->faults0 & axis_faults::undervoltage);
    }
  }
  EXPECT_TRUE(reported);
  rig.board_of(0).set_supply_voltage(12.0);
  rig.to_joint(0, SetControlMode{ControlMode::force_idle});
  EXPECT_EQ(rig.board_of(0).mode(0), ControlMode::idle);
}

}  // namespace
}  // namespace robogene::can::sim
