// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The neck closed on its joint encoders through a gear with backlash (docs/firmware.md "The joint loop"), on the
// simulated boards (the firmware's core on the DC motor model with its dead band): each joint ends on its target
// within two counts of its encoder from either side and stays there; without the joint loop it ends half the gap
// off; a reversed encoder stops the joint with joint_encoder_mismatch, which the driver reports by name; an encoder
// lost while running leaves the joint on its motor encoder. Over the bus with the robogene_can driver, and as
// `robogene can-sim` in its own process with --backlash.
#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "../src/driver/robogene_can.hpp"
#include "board_sim_rig.hpp"
#include "cli_head_session.hpp"
#include "head_rig.hpp"
#include "simulated_head_fixture.hpp"
#include "robogene/can/sim/simulated_head.hpp"
#include "robogene/can/virtual_bus.hpp"
#include "robogene/log.hpp"
#include "test_bus_dir.hpp"

namespace robogene::can {
namespace {

constexpr double kStep = 360.0 / 16384.0;  // one count of the AS5048A, deg
constexpr double kBacklash = 1.0;          // deg at the joint
constexpr int kPitch = 0, kRoll = 1, kYaw = 2;

// Moves a joint to `deg` at 30 deg/s in position mode and gives it `seconds` to settle.
void move(testing::Rig& rig, int joint, double deg, double seconds = 2.0) {
  const JointConfig& j = rig.head.joints[static_cast<std::size_t>(joint)];
  rig.to_joint(joint, SetControlMode{ControlMode::position});
  rig.to_joint(joint, PositionMove{static_cast<std::int32_t>(std::lround(deg * j.counts_per_degree)),
                                   std::round(30 * j.counts_per_degree / 10) * 10});
  rig.run(seconds);
}

class NeckWithBacklash : public ::testing::TestWithParam<int> {};

TEST_P(NeckWithBacklash, EndsOnEachTargetFromEitherSideAndStaysThere) {
  const int joint = GetParam();
  testing::Rig rig;
  const JointConfig& j = rig.head.joints[static_cast<std::size_t>(joint)];
  rig.board_of(joint).set_backlash(j.axis, kBacklash);
  for (const double target : {10.0, 0.0, -10.0}) {
    move(rig, joint, target);
    EXPECT_NEAR(rig.true_degrees(joint), target, 2 * kStep) << j.name << " moved to " << target;
    EXPECT_NEAR(rig.degrees(joint), rig.true_degrees(joint), kStep) << "its position is the joint's";
  }
  // One more second: the joint, the motor, the correction and the drive all hold still (no limit cycle).
  double joint_lo = 1e9, joint_hi = -1e9, motor_lo = 1e9, motor_hi = -1e9;
  int pwm_lo = 100000, pwm_hi = -100000;
  for (int i = 0; i < 100; ++i) {
    rig.run(0.01);
    const double at = rig.true_degrees(joint), motor = rig.board_of(joint).motor_degrees(j.axis);
    joint_lo = std::min(joint_lo, at), joint_hi = std::max(joint_hi, at);
    motor_lo = std::min(motor_lo, motor), motor_hi = std::max(motor_hi, motor);
    const auto r = rig.to_joint(joint, GetPidOutput{});
    ASSERT_TRUE(r);
    const int pwm = std::get<GetPidOutputReply>(r->message).output;
    pwm_lo = std::min(pwm_lo, pwm), pwm_hi = std::max(pwm_hi, pwm);
  }
  EXPECT_NEAR(joint_lo, -10.0, 2 * kStep);
  EXPECT_NEAR(joint_hi, -10.0, 2 * kStep);
  EXPECT_LT(motor_hi - motor_lo, 0.02) << j.name << ": the motor does not cross the gap back and forth";
  // What is left is the motor loop's own dither about its reference, a count each way: (kp + kd) >> shift a count.
  const int per_count = static_cast<int>(std::ceil((j.pid.kp + j.pid.kd) / std::ldexp(1.0, j.pid.shift)));
  EXPECT_LE(pwm_hi - pwm_lo, 2 * per_count) << j.name << ": the drive is steady";
  EXPECT_EQ(rig.board_of(joint).mode(j.axis), ControlMode::position);
}

INSTANTIATE_TEST_SUITE_P(JointLoop, NeckWithBacklash, ::testing::Values(kYaw, kPitch, kRoll),
                         [](const ::testing::TestParamInfo<int>& p) {
                           return std::string(p.param == kYaw ? "neck_yaw" : p.param == kPitch ? "neck_pitch" : "neck_roll");
                         });

// The same head with no joint correction limits (its positions on the motor encoders, as before the joint loop):
// the motor ends on the target, the joint where the gap left it, up to half of it off.
TEST(JointLoop, OnTheMotorEncodersTheJointStopsOffByTheGap) {
  HeadConfig head = testing::head_config();
  for (auto& j : head.joints) j.joint_correction_limit = 0.0;
  testing::Rig rig(head);
  rig.board_of(kYaw).set_backlash(0, kBacklash);
  for (const double target : {10.0, 0.0, -10.0}) {
    move(rig, kYaw, target);
    EXPECT_NEAR(rig.board_of(kYaw).motor_degrees(0), target, 0.02) << "the motor on its target";
    const double off = std::fabs(rig.true_degrees(kYaw) - target);
    EXPECT_GT(off, 4 * kStep) << "moved to " << target << ": twice as far off as the joint loop leaves it, at least";
    EXPECT_LE(off, kBacklash / 2 + 1e-9);
  }
}

// The eye board with an AS5048A on each pan (an edited head; the real eyes have none) and 1 deg of backlash on each
// pan: version and vergence, derived from the two sensors, are closed on them together, and each eye ends on its
// target (left = version + vergence / 2, right = version - vergence / 2).
TEST(JointLoop, TheEyeBoardClosesVersionAndVergenceOnThePanSensors) {
  constexpr int kVersion = 4, kVergence = 5;
  for (const double limit : {3.0, 0.0}) {
    HeadConfig head = testing::head_config();
    for (const int j : {kVersion, kVergence}) {
      head.joints[static_cast<std::size_t>(j)].joint_encoder_bits = 14;
      head.joints[static_cast<std::size_t>(j)].joint_correction_limit = limit;
    }
    testing::Rig rig(head);
    sim::BoardSim& eyes = rig.board_of(kVersion);
    eyes.set_backlash(0, kBacklash);
    eyes.set_backlash(1, kBacklash);
    for (const auto& [version, vergence] : {std::pair{10.0, 4.0}, std::pair{-6.0, 0.0}, std::pair{0.0, 8.0}}) {
      move(rig, kVergence, vergence, 0.0);
      move(rig, kVersion, version, 3.0);
      const double left = eyes.joint_degrees(0), right = eyes.joint_degrees(1);
      if (limit > 0) {
        EXPECT_NEAR(left, version + vergence / 2, 2 * kStep) << "left eye, version " << version << ", vergence " << vergence;
        EXPECT_NEAR(right, version - vergence / 2, 2 * kStep) << "right eye";
        EXPECT_NEAR(rig.degrees(kVersion), (left + right) / 2, kStep) << "version as the pans' sensors give it";
      } else {  // on the motor encoders: at least one eye left in its gap, off by several counts
        EXPECT_GT(std::max(std::fabs(left - version - vergence / 2), std::fabs(right - version + vergence / 2)), 4 * kStep);
      }
    }
    if (limit > 0) {  // and they stay: the eyes and the motors hold still for a second
      std::array<double, 4> lo{{1e9, 1e9, 1e9, 1e9}}, hi{{-1e9, -1e9, -1e9, -1e9}};
      for (int i = 0; i < 100; ++i) {
        rig.run(0.01);
        const std::array<double, 4> now{{eyes.joint_degrees(0), eyes.joint_degrees(1), eyes.motor_degrees(0), eyes.motor_degrees(1)}};
        for (std::size_t k = 0; k < 4; ++k) lo[k] = std::min(lo[k], now[k]), hi[k] = std::max(hi[k], now[k]);
      }
      EXPECT_LT(hi[0] - lo[0], kStep);
      EXPECT_LT(hi[1] - lo[1], kStep);
      EXPECT_LT(hi[2] - lo[2], 0.02) << "the left motor does not cross its gap back and forth";
      EXPECT_LT(hi[3] - lo[3], 0.02) << "nor the right";
    }
    EXPECT_EQ(eyes.mode(0), ControlMode::position);
    EXPECT_EQ(eyes.mode(1), ControlMode::position);
  }
}

// One pan's sensor mounted reversed: version and vergence both run away, and the eye board stops both.
TEST(JointLoop, AReversedPanSensorStopsBothEyeJoints) {
  constexpr int kVersion = 4, kVergence = 5;
  HeadConfig head = testing::head_config();
  for (const int j : {kVersion, kVergence}) {
    head.joints[static_cast<std::size_t>(j)].joint_encoder_bits = 14;
    head.joints[static_cast<std::size_t>(j)].joint_correction_limit = 3.0;
  }
  testing::Rig rig(head);
  sim::BoardSim& eyes = rig.board_of(kVersion);
  eyes.set_joint_encoder_reversed(0, true);
  move(rig, kVergence, 0.0, 0.0);  // both running
  move(rig, kVersion, 15.0, 2.0);
  EXPECT_EQ(eyes.mode(0), ControlMode::hardware_fault);
  EXPECT_EQ(eyes.mode(1), ControlMode::hardware_fault);
  bool both = false;
  for (const auto& e : rig.broadcasts) {
    if (const auto* st = std::get_if<StatusBroadcast>(&e.message); st && e.source == 3) {
      both = both || ((st->faults0 & axis_faults::joint_encoder_mismatch) && (st->faults1 & axis_faults::joint_encoder_mismatch));
    }
  }
  EXPECT_TRUE(both) << "joint_encoder_mismatch on version and vergence";
}

TEST(JointLoop, AReversedEncoderStopsTheJointWithinItsCorrectionLimit) {
  testing::Rig rig;
  const JointConfig& yaw = rig.head.joints[kYaw];
  sim::BoardSim& board = rig.board_of(kYaw);
  board.set_joint_encoder_reversed(0, true);
  board.power_up_at(0.0, 0.0);  // at its 0, where its zero was measured: it homes right
  rig.run(0.01);
  rig.to_joint(kYaw, SetControlMode{ControlMode::position});
  rig.to_joint(kYaw, PositionMove{static_cast<std::int32_t>(std::lround(10 * yaw.counts_per_degree)),
                                  std::round(30 * yaw.counts_per_degree / 10) * 10});
  double beyond = 0.0;
  for (int i = 0; i < 2000 && board.mode(0) == ControlMode::position; ++i) {
    rig.run(0.001);
    beyond = std::max(beyond, rig.true_degrees(kYaw) - 10.0);
  }
  EXPECT_EQ(board.mode(0), ControlMode::hardware_fault);
  const double stopped = rig.true_degrees(kYaw);
  EXPECT_LT(stopped, 10.0 + yaw.joint_correction_limit + 0.5) << "stopped within the limit beyond its target";
  rig.run(1.0);
  EXPECT_NEAR(rig.true_degrees(kYaw), stopped, 0.5) << "and stays stopped";
  bool named = false;
  for (const auto& e : rig.broadcasts) {
    if (const auto* st = std::get_if<StatusBroadcast>(&e.message); st && e.source == yaw.board) {
      named = named || (st->faults0 & axis_faults::joint_encoder_mismatch);
    }
  }
  EXPECT_TRUE(named) << "the status broadcast carries joint_encoder_mismatch";
}

TEST(JointLoop, AnEncoderLostWhileRunningLeavesTheJointOnItsMotorEncoder) {
  testing::Rig rig;
  rig.board_of(kYaw).set_backlash(0, kBacklash);
  move(rig, kYaw, 10.0);
  rig.board_of(kYaw).set_joint_encoder_fault(0, sim::JointEncoderFault::bad_parity);
  move(rig, kYaw, 0.0);
  EXPECT_EQ(rig.board_of(kYaw).mode(0), ControlMode::position) << "not stopped";
  EXPECT_NEAR(rig.degrees(kYaw), 0.0, 2 * kStep) << "reported from the motor encoder, less the last correction";
  // The motor holds where the frozen correction puts it; the joint rests anywhere within the gap of the target.
  EXPECT_LE(std::fabs(rig.true_degrees(kYaw)), kBacklash + kStep) << "the backlash is no longer taken up";
  rig.board_of(kYaw).set_joint_encoder_fault(0, sim::JointEncoderFault::none);
  rig.run(2.0);
  EXPECT_NEAR(rig.true_degrees(kYaw), 0.0, 2 * kStep) << "the sensor back, the joint loop takes over again";
}

// Over the bus: the driver reads the joints at their targets through the backlash, and a reversed encoder's stop is
// refused by name.
class JointLoopOverTheBus : public testing::SimulatedHeadOverBus {};

TEST_F(JointLoopOverTheBus, TheDriverReadsTheNeckAtItsTargetsThroughTheBacklash) {
  sim_->set_backlash(1, 0, kBacklash);  // neck pitch
  sim_->set_backlash(1, 1, kBacklash);  // neck roll
  sim_->set_backlash(2, 0, kBacklash);  // neck yaw
  open();
  const std::vector<double> targets = {8.0, -6.0, 15.0};
  for (int j = 0; j < 3; ++j) {
    ASSERT_TRUE(driver_.setRefSpeed(j, 30.0));
    ASSERT_TRUE(driver_.positionMove(j, targets[static_cast<std::size_t>(j)])) << driver_.last_error();
  }
  // The joint loop settles after the reference has arrived: a joint the motor loop's overshoot pushed past its target
  // waits for the motor to cross the gap back. Then it stays.
  const auto all_there = [&] {
    for (int j = 0; j < 3; ++j) {
      const JointConfig& jc = head_.joints[static_cast<std::size_t>(j)];
      double v = 0;
      const double target = targets[static_cast<std::size_t>(j)];
      if (!driver_.getEncoder(j, v) || std::fabs(v - target) > 2 * kStep ||
          std::fabs(sim_->joint_degrees(jc.board, jc.axis) - target) > 2 * kStep) {
        return false;
      }
    }
    return true;
  };
  EXPECT_TRUE(testing::eventually(8.0, all_there));
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));
  for (int j = 0; j < 3; ++j) {
    const JointConfig& jc = head_.joints[static_cast<std::size_t>(j)];
    const double target = targets[static_cast<std::size_t>(j)];
    EXPECT_NEAR(sim_->joint_degrees(jc.board, jc.axis), target, 2 * kStep) << jc.name;
    double v = 0;
    ASSERT_TRUE(driver_.getEncoder(j, v));
    EXPECT_NEAR(v, target, 2 * kStep) << jc.name << " as the driver reads it";
  }
}

TEST_F(JointLoopOverTheBus, AReversedEncoderIsReportedByName) {
  std::mutex lock;
  std::vector<std::string> errors;
  struct SinkGuard {
    ~SinkGuard() { log::set_sink({}); }
  } sink_guard;
  log::set_sink([&](log::Level level, std::string_view, std::string_view text) {
    std::lock_guard<std::mutex> g(lock);
    if (level == log::Level::Error) errors.emplace_back(text);
  });
  sim_->set_joint_encoder_reversed(2, 0, true);
  open();
  ASSERT_TRUE(driver_.setRefSpeed(kYaw, 30.0));
  ASSERT_TRUE(driver_.positionMove(kYaw, 10.0)) << driver_.last_error();
  // The board stops the joint; the next move is refused with the fault's name.
  EXPECT_TRUE(testing::eventually(3.0, [&] {
    return !driver_.positionMove(kYaw, 10.0) && driver_.last_error().find("joint_encoder_mismatch") != std::string::npos;
  })) << driver_.last_error();
  EXPECT_NE(driver_.last_error().find("joint neck_yaw was stopped by board 2"), std::string::npos) << driver_.last_error();
  const double stopped = sim_->joint_degrees(2, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_NEAR(sim_->joint_degrees(2, 0), stopped, 0.5) << "the motion stopped";
  std::lock_guard<std::mutex> g(lock);
  const bool logged = std::any_of(errors.begin(), errors.end(), [](const std::string& e) {
    return e.find("board 2 reports faults: axis 0: joint_encoder_mismatch") != std::string::npos;
  });
  EXPECT_TRUE(logged) << "the driver logs the board's fault by name";
}

// `robogene can-sim --backlash` in its own process: the driver reads the neck at its targets.
TEST(JointLoopCanSim, WithBacklashTheDriverReadsTheNeckAtItsTargets) {
  testing::TempBusDir dir;
  testing::ChildGuard guard{testing::start_simulator(
      "virtual:backlash", dir.path() + "/sim.log", "",
      {"--backlash", "neck_pitch=1", "--backlash", "neck_yaw=1.5", "--backlash", "eyes_tilt=0.8"})};
  ASSERT_GT(guard.pid, 0);
  RobogeneCan driver;
  ASSERT_TRUE(testing::eventually(10.0, [&] { return driver.open(testing::driver_config("virtual:backlash")); }))
      << driver.last_error();
  const HeadConfig head = testing::head_config();
  const std::vector<std::pair<int, double>> targets = {{kPitch, -12.0}, {kYaw, 20.0}, {3, 9.0}};
  for (const auto& [j, deg] : targets) {
    ASSERT_TRUE(driver.setRefSpeed(j, 30.0));
    ASSERT_TRUE(driver.positionMove(j, deg)) << driver.last_error();
  }
  // The joint as its own sensor reads it (get_joint_encoder: raw angle less the zero), and as the driver reads it.
  const auto sensed = [&](int j) { return driver.joint_encoder(j).joint_degrees.value_or(1e9); };
  const auto all_there = [&] {
    for (const auto& [j, deg] : targets) {
      double v = 0;
      if (!driver.getEncoder(j, v) || std::fabs(v - deg) > 2 * kStep || std::fabs(sensed(j) - deg) > 2 * kStep) return false;
    }
    return true;
  };
  EXPECT_TRUE(testing::eventually(8.0, all_there));
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));  // and they stay
  for (const auto& [j, deg] : targets) {
    double v = 0;
    ASSERT_TRUE(driver.getEncoder(j, v));
    EXPECT_NEAR(v, deg, 2 * kStep) << head.joints[static_cast<std::size_t>(j)].name;
    EXPECT_NEAR(sensed(j), deg, 2 * kStep) << head.joints[static_cast<std::size_t>(j)].name << " as its sensor reads it";
  }
  driver.close();
}

}  // namespace
}  // namespace robogene::can
