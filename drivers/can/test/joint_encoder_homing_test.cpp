// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The neck and the eye tilt take their positions from their AS5048A joint encoders at power-up: the
// simulated head powered up at a pose of its own, read by the robogene_can driver; a missing or
// failing encoder, or a board with no zero stored, leaving the joint refusing to move with the reason;
// the lab's zero stored over the bus (driver and `robogene can-zero`) and kept across a power cycle.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "../src/driver/robogene_can.hpp"
#include "cli_head_session.hpp"
#include "head_rig.hpp"
#include "simulated_head_fixture.hpp"
#include "robogene/can/joint_encoders.hpp"
#include "robogene/can/sim/simulated_head.hpp"
#include "robogene/can/virtual_bus.hpp"
#include "test_bus_dir.hpp"

namespace robogene::can {
namespace {

constexpr double kOneStep = 360.0 / 16384.0;  // the AS5048A's resolution, deg

class JointEncoderHoming : public testing::SimulatedHeadOverBus {
 protected:
  double encoder(int j) {
    double v = 0;
    EXPECT_TRUE(testing::eventually(1.0, [&] { return driver_.getEncoder(j, v); })) << driver_.last_error();
    return v;
  }
};

TEST_F(JointEncoderHoming, TheNeckAndTiltComeUpAtTheirTruePose) {
  sim_->power_up_at(1, 12.0, -7.5);   // neck pitch, roll
  sim_->power_up_at(2, 20.0, -10.0);  // neck yaw, eye tilt
  open();
  EXPECT_NEAR(encoder(0), 12.0, kOneStep);
  EXPECT_NEAR(encoder(1), -7.5, kOneStep);
  EXPECT_NEAR(encoder(2), 20.0, kOneStep);
  EXPECT_NEAR(encoder(3), -10.0, kOneStep);
  for (int j = 0; j < 4; ++j) EXPECT_TRUE(driver_.joint_encoder(j).homed) << head_.joints[static_cast<std::size_t>(j)].name;
  // The joint's 0 is its true 0.
  ASSERT_TRUE(driver_.setRefSpeed(0, 40.0));
  ASSERT_TRUE(driver_.positionMove(0, 0.0)) << driver_.last_error();
  ASSERT_TRUE(testing::eventually(3.0, [&] { return std::fabs(sim_->motor_degrees(1, 0)) < 0.1; }))
      << "neck pitch at " << sim_->motor_degrees(1, 0);
}

TEST_F(JointEncoderHoming, AMissingEncoderLeavesItsJointRefusingToMove) {
  sim_->set_joint_encoder_fault(1, 1, sim::JointEncoderFault::missing);
  sim_->power_up_at(1, 5.0, 6.0);
  open();
  const JointEncoderReading r = driver_.joint_encoder(1);
  EXPECT_EQ(r.state, "absent");
  EXPECT_FALSE(r.homed);
  EXPECT_FALSE(driver_.positionMove(1, 0.0));
  EXPECT_NE(driver_.last_error().find("joint neck_roll is not homed"), std::string::npos) << driver_.last_error();
  EXPECT_NE(driver_.last_error().find("absent"), std::string::npos) << driver_.last_error();
  EXPECT_FALSE(driver_.velocityMove(1, 5.0));
  EXPECT_FALSE(driver_.setControlMode(1, dev::ControlMode::position));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_NEAR(sim_->motor_degrees(1, 1), 6.0, 1e-6) << "the roll did not move";
  // Its neighbour on the same board homed and runs.
  EXPECT_NEAR(encoder(0), 5.0, kOneStep);
  ASSERT_TRUE(driver_.positionMove(0, 0.0)) << driver_.last_error();
  ASSERT_TRUE(testing::eventually(3.0, [&] { return std::fabs(sim_->motor_degrees(1, 0)) < 0.1; }));
}

TEST_F(JointEncoderHoming, BadParityAndTheErrorFlagFailTheEncoder) {
  sim_->set_joint_encoder_fault(2, 0, sim::JointEncoderFault::bad_parity);
  sim_->set_joint_encoder_fault(2, 1, sim::JointEncoderFault::error_flag);
  sim_->power_up_at(2, 3.0, 4.0);
  open();
  EXPECT_EQ(driver_.joint_encoder(2).state, "failed");
  EXPECT_EQ(driver_.joint_encoder(3).state, "failed");
  EXPECT_FALSE(driver_.positionMove(2, 0.0));
  EXPECT_NE(driver_.last_error().find("joint neck_yaw is not homed"), std::string::npos) << driver_.last_error();
  EXPECT_FALSE(driver_.positionMove(3, 0.0));
}

TEST_F(JointEncoderHoming, TheLabStoresAZeroAndTheJointHomesFromItAtEveryPowerUp) {
  sim_->set_stored_joint_zero(1, 0, std::nullopt);  // a board fresh from flashing
  sim_->power_up_at(1, 0.0, 0.0);                   // the pitch held at its 0 deg pose
  open();
  EXPECT_FALSE(driver_.positionMove(0, 5.0));
  EXPECT_NE(driver_.last_error().find("no zero stored"), std::string::npos) << driver_.last_error();
  JointEncoderReading r = driver_.joint_encoder(0);
  EXPECT_EQ(r.state, "ok");
  EXPECT_FALSE(r.zero_stored);
  EXPECT_EQ(r.raw, sim_->joint_encoder_magnet(1, 0)) << "at 0 deg the sensor reads its magnet's angle";
  r = driver_.store_joint_encoder_zero(0, r.raw);
  EXPECT_TRUE(r.homed);
  ASSERT_TRUE(r.joint_degrees);
  EXPECT_NEAR(*r.joint_degrees, 0.0, kOneStep);
  EXPECT_EQ(sim_->stored_joint_zero(1, 0), std::optional<std::uint16_t>(r.raw)) << "kept in the board's flash";
  ASSERT_TRUE(driver_.setRefSpeed(0, 40.0));
  ASSERT_TRUE(driver_.positionMove(0, 5.0)) << driver_.last_error();
  ASSERT_TRUE(testing::eventually(3.0, [&] { return std::fabs(sim_->motor_degrees(1, 0) - 5.0) < 0.1; }));
  // Powered up elsewhere, the board homes from the stored zero.
  sim_->power_up_at(1, -9.0, 0.0);
  ASSERT_TRUE(testing::eventually(2.0, [&] {
    double v = 0;
    return driver_.getEncoder(0, v) && std::fabs(v + 9.0) < kOneStep;
  }));
}

TEST_F(JointEncoderHoming, BadZerosAndJointsWithoutAnEncoderAreRefusedByName) {
  open();
  try {
    driver_.store_joint_encoder_zero(0, 16384);
    FAIL() << "a zero beyond 14 bits";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("joint 'neck_pitch': zero 16384 is beyond its 14-bit encoder (0..16383)"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(driver_.joint_encoder(4), Error);
  // A running joint keeps its zero.
  const std::uint16_t magnet = sim_->joint_encoder_magnet(1, 0);
  try {
    driver_.store_joint_encoder_zero(0, static_cast<std::uint16_t>(magnet + 1));
    FAIL() << "the pitch runs in position mode since the driver opened";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("did not take the zero (a running joint keeps its zero"), std::string::npos) << e.what();
  }
  // A zero that puts the joint far outside its range is taken by the board but does not home it.
  ASSERT_TRUE(driver_.setControlMode(0, dev::ControlMode::idle)) << driver_.last_error();
  const std::uint16_t off = static_cast<std::uint16_t>((magnet + 8192) % 16384);
  try {
    driver_.store_joint_encoder_zero(0, off);
    FAIL() << "a zero half a turn off";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("did not home the joint"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(driver_.positionMove(0, 1.0));
  EXPECT_NE(driver_.last_error().find("outside the joint's range"), std::string::npos) << driver_.last_error();
}

// A head whose eye pans have AS5048As too (an edited head.ini: the real one gives the eyes none): the eye
// board derives version and vergence from the two pans' sensors at power-up.
TEST(JointEncoderEyes, TheEyeBoardComesUpAtItsTrueVersionAndVergence) {
  testing::TempBusDir dir;
  std::ifstream in(testing::head_ini_path());
  std::stringstream text;
  text << in.rdbuf();
  std::string ini = text.str();
  const std::string bits = "joint_encoder_bits 14 14 14 14 0 0";
  ASSERT_NE(ini.find(bits), std::string::npos);
  ini.replace(ini.find(bits), bits.size(), "joint_encoder_bits 14 14 14 14 14 14");
  dev::Property config = dev::Property::from_ini(ini, "head.ini");
  const HeadConfig head = read_head_config(config);
  sim::SimulatedHead sim(head, std::make_unique<VirtualBus>("head"));
  sim.power_up_at(3, 10.0, 4.0);  // left pan 10 deg, right pan 4 deg
  config.put("bus", Value(std::string("virtual:head")));
  RobogeneCan driver;
  ASSERT_TRUE(driver.open(config)) << driver.last_error();
  double version = 0, vergence = 0;
  ASSERT_TRUE(testing::eventually(1.0, [&] { return driver.getEncoder(4, version) && driver.getEncoder(5, vergence); }));
  EXPECT_NEAR(version, 7.0, kOneStep);
  EXPECT_NEAR(vergence, 6.0, 2 * kOneStep);
  const JointEncoderReading left = driver.joint_encoder(4), right = driver.joint_encoder(5);
  EXPECT_EQ(left.measures, "left_eye_pan");
  EXPECT_EQ(right.measures, "right_eye_pan");
  ASSERT_TRUE(left.joint_degrees && right.joint_degrees);
  EXPECT_NEAR(*left.joint_degrees, 10.0, kOneStep);
  EXPECT_NEAR(*right.joint_degrees, 4.0, kOneStep);
  ASSERT_TRUE(driver.positionMove(5, 0.0)) << driver.last_error();
  ASSERT_TRUE(driver.positionMove(4, 0.0)) << driver.last_error();
  ASSERT_TRUE(testing::eventually(4.0, [&] {
    return std::fabs(sim.motor_degrees(3, 0)) < 0.1 && std::fabs(sim.motor_degrees(3, 1)) < 0.1;
  })) << "pans at " << sim.motor_degrees(3, 0) << ", " << sim.motor_degrees(3, 1);
  driver.close();
}

int run_cli(const std::string& args, std::string& out) {
  const std::string cmd = testing::robogene_bin() + " can-zero --bus virtual:zero --from " + testing::head_ini_path() + " " + args + " 2>&1";
  FILE* p = ::popen(cmd.c_str(), "r");
  char buf[512];
  while (p && std::fgets(buf, sizeof buf, p)) out += buf;
  const int status = p ? ::pclose(p) : -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// `robogene can-zero` against `robogene can-sim`, each its own process on the virtual bus.
TEST(JointEncoderCli, CanZeroReadsTheEncodersAndRefusesBadRequestsByName) {
  testing::TempBusDir dir;
  testing::ChildGuard guard{testing::start_simulator("virtual:zero", dir.path() + "/sim.log")};
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the simulator binds its node
  std::string out;
  ASSERT_EQ(run_cli("", out), 0) << out;
  for (const char* joint : {"neck_pitch", "neck_roll", "neck_yaw", "eyes_tilt"}) {
    EXPECT_NE(out.find(std::string("can-zero: ") + joint + ": encoder ok, raw "), std::string::npos) << joint << "\n" << out;
  }
  EXPECT_NE(out.find("stored, homed, joint at 0.00 deg"), std::string::npos) << out;
  out.clear();
  EXPECT_EQ(run_cli("--store eyes_version", out), 1) << out;
  EXPECT_NE(out.find("joint 'eyes_version' has no joint encoder"), std::string::npos) << out;
  out.clear();
  EXPECT_EQ(run_cli("--store neck_pitch=12x", out), 2) << out;
  EXPECT_NE(out.find("the zero '12x' is not a raw encoder count"), std::string::npos) << out;
  out.clear();
  ASSERT_EQ(run_cli("--store neck_yaw", out), 0) << out;  // the yaw is at 0: its raw angle now is its zero
  EXPECT_NE(out.find("can-zero: neck_yaw: encoder ok"), std::string::npos) << out;
}

// can-sim's --pose, which the head session (here and in the VM) powers the neck up with, refuses what it cannot use.
TEST(JointEncoderCli, CanSimRefusesABadPoseByName) {
  testing::TempBusDir dir;
  for (const auto& [pose, message] : {std::pair<std::string, std::string>{"neck_twist=3", "'neck_twist=3' is not JOINT=DEG"},
                                      {"neck_pitch=12,neck_roll", "'neck_roll' is not JOINT=DEG"},
                                      {"neck_pitch=twelve", "'twelve' (neck_pitch) is not an angle in degrees"}}) {
    const std::string cmd = testing::robogene_bin() + " can-sim --bus virtual:pose --duration 1 --from " + testing::head_ini_path() +
                            " --pose " + pose + " 2>&1";
    std::string out;
    FILE* p = ::popen(cmd.c_str(), "r");
    char buf[512];
    while (p && std::fgets(buf, sizeof buf, p)) out += buf;
    const int status = p ? ::pclose(p) : -1;
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << pose << ": " << out;
    EXPECT_NE(out.find(message), std::string::npos) << out;
  }
}

}  // namespace
}  // namespace robogene::can
