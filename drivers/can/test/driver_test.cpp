// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The robogene_can driver, created through the factory, driving a simulated head on the virtual
// bus: every joint through position and velocity commands with the encoders tracking, the eye
// coupling down to the two eye motors, PIDs, modes, and bus errors surfacing as failures.
#include <cmath>

#include <gtest/gtest.h>

#include "head_rig.hpp"
#include "robogene/can/sim/simulated_head.hpp"
#include "../src/driver/robogene_can.hpp"
#include "robogene/can/virtual_bus.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "test_bus_dir.hpp"

namespace robogene::can {
namespace {

using dev::ControlMode;

class DriverOnVirtualBus : public ::testing::Test {
 protected:
  void SetUp() override {
    head_ = testing::head_config();
    sim_ = std::make_unique<sim::SimulatedHead>(head_, std::make_unique<VirtualBus>("head"));
    ASSERT_TRUE(device_.open(testing::driver_config("virtual:head"))) << device_.last_error();
    ASSERT_TRUE(device_.view(enc_) && device_.view(pos_) && device_.view(vel_) && device_.view(pid_) && device_.view(mode_));
  }
  void TearDown() override {
    device_.close();
    sim_.reset();
  }

  ::robogene::can::testing::TempBusDir dir_;
  HeadConfig head_;
  std::unique_ptr<sim::SimulatedHead> sim_;
  dev::PolyDriver device_;
  dev::IEncoders* enc_ = nullptr;
  dev::IPositionControl* pos_ = nullptr;
  dev::IVelocityControl* vel_ = nullptr;
  dev::IPidControl* pid_ = nullptr;
  dev::IControlMode* mode_ = nullptr;
};

TEST_F(DriverOnVirtualBus, EveryJointFollowsPositionThenVelocityCommandsWithEncodersTracking) {
  std::int32_t axes = 0;
  ASSERT_TRUE(pos_->getAxes(axes));
  ASSERT_EQ(axes, 6);
  std::vector<double> targets;
  for (const auto& j : head_.joints) targets.push_back(j.min + 0.7 * (j.max - j.min));
  ASSERT_TRUE(pos_->setRefSpeeds(std::vector<double>(6, 40.0)));
  ASSERT_TRUE(pos_->setRefAccelerations(std::vector<double>(6, 200.0)));
  ASSERT_TRUE(pos_->positionMove(targets));
  std::vector<double> target_back;
  ASSERT_TRUE(pos_->getTargetPositions(target_back));
  for (int j = 0; j < 6; ++j) EXPECT_NEAR(target_back[static_cast<std::size_t>(j)], targets[static_cast<std::size_t>(j)], 0.01);
  // Halfway there, the encoders are moving towards the targets.
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  std::vector<double> mid;
  ASSERT_TRUE(enc_->getEncoders(mid));
  for (int j = 0; j < 6; ++j) {
    EXPECT_GT(mid[static_cast<std::size_t>(j)] * targets[static_cast<std::size_t>(j)], 0.0) << head_.joints[static_cast<std::size_t>(j)].name;
  }
  ASSERT_TRUE(testing::eventually(6.0, [&] {
    bool done = false;
    return pos_->checkMotionDone(done) && done;
  }));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  std::vector<double> at;
  ASSERT_TRUE(enc_->getEncoders(at));
  for (int j = 0; j < 6; ++j) {
    EXPECT_NEAR(at[static_cast<std::size_t>(j)], targets[static_cast<std::size_t>(j)], 0.1) << head_.joints[static_cast<std::size_t>(j)].name;
  }
  std::vector<ControlMode> modes;
  ASSERT_TRUE(mode_->getControlModes(modes));
  EXPECT_EQ(modes, std::vector<ControlMode>(6, ControlMode::position));

  // Velocity: every joint back towards its middle at 8 deg/s; encoders and speeds follow.
  std::vector<double> speeds;
  for (int j = 0; j < 6; ++j) speeds.push_back(targets[static_cast<std::size_t>(j)] > 0 ? -8.0 : 8.0);
  ASSERT_TRUE(vel_->velocityMove(speeds));
  ASSERT_TRUE(mode_->getControlModes(modes));
  EXPECT_EQ(modes, std::vector<ControlMode>(6, ControlMode::velocity));
  std::this_thread::sleep_for(std::chrono::milliseconds(800));  // longer than the 100 ms velocity timeout: refreshed
  std::vector<double> measured_speed;
  ASSERT_TRUE(enc_->getEncoderSpeeds(measured_speed));
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  std::vector<double> later;
  ASSERT_TRUE(enc_->getEncoders(later));
  for (int j = 0; j < 6; ++j) {
    const auto i = static_cast<std::size_t>(j);
    EXPECT_NEAR(measured_speed[i], speeds[i], 1.5) << head_.joints[i].name;
    EXPECT_NEAR(later[i] - at[i], speeds[i] * 1.2, 2.5) << head_.joints[i].name;
  }
  ASSERT_TRUE(pos_->stop());
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  std::vector<double> stopped, after;
  ASSERT_TRUE(enc_->getEncoders(stopped));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_TRUE(enc_->getEncoders(after));
  for (int j = 0; j < 6; ++j) EXPECT_NEAR(after[static_cast<std::size_t>(j)], stopped[static_cast<std::size_t>(j)], 0.1);
}

TEST_F(DriverOnVirtualBus, VersionAndVergenceMoveTheTwoEyeMotorsAsCoupled) {
  ASSERT_TRUE(pos_->setRefSpeed(4, 60.0) && pos_->setRefSpeed(5, 60.0));
  ASSERT_TRUE(pos_->positionMove(4, 10.0));
  ASSERT_TRUE(pos_->positionMove(5, 20.0));
  const int eyes = head_.joints[4].board;
  ASSERT_TRUE(testing::eventually(4.0, [&] {
    bool v = false, g = false;
    return pos_->checkMotionDone(4, v) && pos_->checkMotionDone(5, g) && v && g;
  }));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  // left = version + vergence / 2, right = version - vergence / 2 (the config's j2m)
  EXPECT_NEAR(sim_->motor_degrees(eyes, 0), 20.0, 0.1);
  EXPECT_NEAR(sim_->motor_degrees(eyes, 1), 0.0, 0.1);
  double version = 0, vergence = 0;
  ASSERT_TRUE(enc_->getEncoder(4, version) && enc_->getEncoder(5, vergence));
  EXPECT_NEAR(version, 10.0, 0.1);
  EXPECT_NEAR(vergence, 20.0, 0.1);
}

TEST_F(DriverOnVirtualBus, PidsRoundTripAndOtherLoopsAreRefused) {
  dev::Pid pid;
  ASSERT_TRUE(pid_->getPid(dev::PidType::position, 2, pid));
  EXPECT_EQ(pid.kp, head_.joints[2].pid.kp);
  EXPECT_EQ(pid.kd, head_.joints[2].pid.kd);
  EXPECT_EQ(pid.max_output, head_.joints[2].pid.output_limit);
  pid.kp = 80;
  pid.max_int = 250;
  ASSERT_TRUE(pid_->setPid(dev::PidType::position, 2, pid));
  dev::Pid back;
  ASSERT_TRUE(pid_->getPid(dev::PidType::position, 2, back));
  EXPECT_EQ(back.kp, 80);
  EXPECT_EQ(back.max_int, 250);
  EXPECT_FALSE(pid_->getPid(dev::PidType::torque, 2, pid));
  pid.kp = 1e6;
  EXPECT_FALSE(pid_->setPid(dev::PidType::position, 2, pid));
  double out = 0;
  EXPECT_TRUE(pid_->getPidOutput(dev::PidType::position, 0, out));
}

TEST_F(DriverOnVirtualBus, PidOffsetIsSentAndTheRequestsTheBoardsLackFailSayingSo) {
  dev::Pid before;
  ASSERT_TRUE(pid_->getPid(dev::PidType::position, 1, before));
  ASSERT_TRUE(pid_->setPidOffset(dev::PidType::position, 1, 12.0));
  dev::Pid after;
  ASSERT_TRUE(pid_->getPid(dev::PidType::position, 1, after));
  dev::Pid expected = before;
  expected.offset = 12.0;  // the limits sent with it are the board's own
  EXPECT_EQ(after, expected);
  RobogeneCan* driver = nullptr;
  ASSERT_TRUE(device_.view(driver));
  EXPECT_FALSE(pid_->setPidOffset(dev::PidType::position, 1, 0.5));
  EXPECT_NE(driver->last_error().find("setPidOffset (joint 1): PID offset 0.5"), std::string::npos) << driver->last_error();
  EXPECT_FALSE(pid_->setPidOffset(dev::PidType::velocity, 1, 1.0));
  EXPECT_NE(driver->last_error().find("no velocity PID, only a position PID"), std::string::npos) << driver->last_error();

  EXPECT_FALSE(pid_->enablePid(dev::PidType::position, 0));
  EXPECT_EQ(driver->last_error(),
            "enablePid (joint 0): the boards' protocol has no command to switch a PID on or off (use setControlMode)");
  EXPECT_FALSE(pid_->disablePid(dev::PidType::position, 0));
  EXPECT_NE(driver->last_error().find("disablePid (joint 0): the boards' protocol has no command"), std::string::npos);
  EXPECT_FALSE(pid_->resetPid(dev::PidType::position, 0));
  EXPECT_EQ(driver->last_error(), "resetPid (joint 0): the boards' protocol has no command to reset a PID");
  bool enabled = false;
  EXPECT_FALSE(pid_->isPidEnabled(dev::PidType::position, 0, enabled));
  EXPECT_NE(driver->last_error().find("isPidEnabled (joint 0): the boards' protocol does not report"), std::string::npos);
  EXPECT_FALSE(pid_->resetPid(dev::PidType::position, 9));
  EXPECT_EQ(driver->last_error(), "resetPid (joint 9): no joint 9 (the head has 6)");
  // Nothing above moved or changed the boards: the gains are as set.
  ASSERT_TRUE(pid_->getPid(dev::PidType::position, 1, after));
  EXPECT_EQ(after, expected);
}

TEST_F(DriverOnVirtualBus, ModesTheBoardsDoNotHaveAreReportedNotAssumed) {
  ASSERT_TRUE(mode_->setControlMode(1, ControlMode::idle));
  ControlMode m{};
  ASSERT_TRUE(mode_->getControlMode(1, m));
  EXPECT_EQ(m, ControlMode::idle);
  EXPECT_FALSE(mode_->setControlMode(1, ControlMode::torque));
  RobogeneCan* driver = nullptr;
  ASSERT_TRUE(device_.view(driver));
  EXPECT_NE(driver->last_error().find("stayed in mode idle instead of torque"), std::string::npos) << driver->last_error();
  EXPECT_FALSE(pos_->positionMove(6, 1.0));
  EXPECT_NE(driver->last_error().find("no joint 6"), std::string::npos) << driver->last_error();
}

TEST_F(DriverOnVirtualBus, AVectorWithOneBadEntryChangesNothing) {
  std::vector<double> before;
  ASSERT_TRUE(pos_->getTargetPositions(before));
  std::vector<double> targets(6, 5.0);
  targets[3] = std::nan("");
  EXPECT_FALSE(pos_->positionMove(targets));
  EXPECT_FALSE(pos_->positionMove(std::vector<double>(5, 1.0)));
  std::vector<double> speeds(6, 20.0);
  speeds[5] = -1.0;
  EXPECT_FALSE(pos_->setRefSpeeds(speeds));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  std::vector<double> after, ref_speeds;
  ASSERT_TRUE(pos_->getTargetPositions(after));
  EXPECT_EQ(after, before);
  ASSERT_TRUE(pos_->getRefSpeeds(ref_speeds));
  EXPECT_EQ(ref_speeds, std::vector<double>(6, 10.0));
}

TEST_F(DriverOnVirtualBus, BusOffSurfacesAsFailuresUntilTheControllerRestarts) {
  RobogeneCan* driver = nullptr;
  ASSERT_TRUE(device_.view(driver));
  VirtualBus tester("head");
  tester.inject_error(make_error_frame(BusErrorKind::bus_off));
  ASSERT_TRUE(testing::eventually(2.0, [&] { return !pos_->positionMove(0, 5.0); }));
  EXPECT_NE(driver->last_error().find("bus-off"), std::string::npos) << driver->last_error();
  double v = 0;
  EXPECT_FALSE(enc_->getEncoder(0, v));
  tester.inject_error(make_error_frame(BusErrorKind::restarted));
  EXPECT_TRUE(testing::eventually(2.0, [&] { return pos_->positionMove(0, 5.0); })) << driver->last_error();
}

TEST_F(DriverOnVirtualBus, ASilentBoardIsReportedNotReadAsStale) {
  RobogeneCan* driver = nullptr;
  ASSERT_TRUE(device_.view(driver));
  sim_->stop();
  double v = 0;
  EXPECT_TRUE(testing::eventually(2.0, [&] { return !enc_->getEncoder(0, v); }));
  EXPECT_NE(driver->last_error().find("has broadcast no position"), std::string::npos) << driver->last_error();
  bool done = false;
  EXPECT_FALSE(pos_->checkMotionDone(0, done));
  EXPECT_NE(driver->last_error().find("did not answer motion_done within 500 ms"), std::string::npos) << driver->last_error();
}

TEST(DriverOpen, NoBoardOnTheBusIsNamed) {
  ::robogene::can::testing::TempBusDir dir;
  dev::PolyDriver device;
  EXPECT_FALSE(device.open(testing::driver_config("virtual:empty")));
  EXPECT_NE(device.last_error().find("board 1 axis 0 did not answer get_firmware_version"), std::string::npos) << device.last_error();
}

TEST(DriverOpen, ABadConfigNamesTheField) {
  ::robogene::can::testing::TempBusDir dir;
  dev::Property broken = dev::Property::from_ini("[CAN]\ndevice \"can0\"\n", "broken.ini");
  broken.put("device", Value(std::string("robogene_can")));
  dev::PolyDriver device;
  EXPECT_FALSE(device.open(broken));
  EXPECT_NE(device.last_error().find("broken.ini"), std::string::npos) << device.last_error();
  EXPECT_NE(device.last_error().find("host_address"), std::string::npos) << device.last_error();
  dev::Property bad_bus = testing::driver_config("serial:ttyS0");
  EXPECT_FALSE(device.open(bad_bus));
  EXPECT_NE(device.last_error().find("serial:ttyS0"), std::string::npos) << device.last_error();
}

}  // namespace
}  // namespace robogene::can
