// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Homing from the host (robogene::can::home_joints, behind `robogene can-home`) against the
// simulated head on the virtual bus: the eyes powered up somewhere unknown to their board.
#include <cstdio>
#include <thread>

#include <gtest/gtest.h>

#include "cli_head_session.hpp"
#include "head_config_fixture.hpp"
#include "robogene/can/homing.hpp"
#include "robogene/can/sim/simulated_head.hpp"
#include "robogene/can/virtual_bus.hpp"
#include "test_bus_dir.hpp"

namespace robogene::can {
namespace {

TEST(Homing, EyesHomeOverTheBusAndReportWhereTheyAre) {
  testing::TempBusDir dir;
  const HeadConfig head = testing::head_config();
  sim::SimulatedHead sim(head, std::make_unique<VirtualBus>("head"));
  sim.power_up_at(3, -20.0, 10.0);
  std::vector<std::string> lines;
  const auto results = home_joints(std::make_unique<VirtualBus>("head"), head, {}, [&](const std::string& l) { lines.push_back(l); });
  ASSERT_EQ(results.size(), 1u) << "only version homes; vergence is found with it";
  EXPECT_EQ(results[0].joint, "eyes_version");
  ASSERT_TRUE(results[0].homed) << results[0].detail;
  const JointConfig& v = head.joints[4];
  EXPECT_NEAR(results[0].degrees, v.homing.stop - v.homing.backoff, 0.3);
  // The board's counts are the eyes' true angles now.
  const double left = sim.motor_degrees(3, 0), right = sim.motor_degrees(3, 1);
  EXPECT_NEAR(sim.measured_counts(3, 0) / v.counts_per_degree, (left + right) / 2, 0.05);
  EXPECT_NEAR(sim.measured_counts(3, 1) / head.joints[5].counts_per_degree, left - right, 0.05);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "eyes_version: homing on board 3 axis 0");
}

TEST(Homing, AStopNotFoundInTimeIsReportedAsNotHomed) {
  testing::TempBusDir dir;
  HeadConfig head = testing::head_config();
  HeadConfig board_side = head;
  board_side.joints[4].homing.timeout = 0.5;  // the firmware gives up long before the stop
  sim::SimulatedHead sim(board_side, std::make_unique<VirtualBus>("head"));
  const auto results = home_joints(std::make_unique<VirtualBus>("head"), head, {"eyes_version"});
  ASSERT_EQ(results.size(), 1u);
  EXPECT_FALSE(results[0].homed);
  EXPECT_NE(results[0].detail.find("found no stop within"), std::string::npos) << results[0].detail;
}

TEST(Homing, JointsThatDoNotHomeAreRefusedByName) {
  testing::TempBusDir dir;
  const HeadConfig head = testing::head_config();
  try {
    home_joints(std::make_unique<VirtualBus>("head"), head, {"neck_pitch"});
    FAIL() << "neck_pitch has an absolute encoder and no homing";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("joint 'neck_pitch' does not home ([HOMING] direction 0); the joints that home: eyes_version"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(home_joints(std::make_unique<VirtualBus>("head"), head, {"neck_twist"}), Error);
}

// `robogene can-home` against `robogene can-sim`, each its own process on the virtual bus.
TEST(Homing, TheCanHomeCommandHomesTheSimulatorsEyesAndRefusesAJointThatDoesNotHome) {
  testing::TempBusDir dir;
  const pid_t sim = testing::start_simulator("virtual:homing", dir.path() + "/sim.log");
  testing::ChildGuard guard{sim};
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the simulator binds its node
  auto run = [](const std::string& args, std::string& out) {
    const std::string cmd = testing::robogene_bin() + " can-home --bus virtual:homing --from " + testing::head_ini_path() +
                            " " + args + " 2>&1";
    FILE* p = ::popen(cmd.c_str(), "r");
    char buf[512];
    while (p && std::fgets(buf, sizeof buf, p)) out += buf;
    const int status = p ? ::pclose(p) : -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  std::string out;
  EXPECT_EQ(run("", out), 0) << out;
  EXPECT_NE(out.find("can-home: eyes_version: homing on board 3 axis 0"), std::string::npos) << out;
  EXPECT_NE(out.find("can-home: eyes_version homed, now at 27."), std::string::npos) << out;
  std::string refused;
  EXPECT_EQ(run("neck_yaw", refused), 1) << refused;
  EXPECT_NE(refused.find("joint 'neck_yaw' does not home"), std::string::npos) << refused;
}

}  // namespace
}  // namespace robogene::can
