// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>

#include "cli_head_session.hpp"
#include "socketcan_env.hpp"
#include "test_bus_dir.hpp"

namespace robogene::can {
namespace {

TEST(CanHeadOverVirtualBus, CanSimProcessAndDriverMoveEveryJoint) {
  testing::TempBusDir dir;
  testing::run_head_session("virtual:session", dir.path());
}

// The same session with 1 deg of backlash between each neck and tilt motor and its joint: every move and read of the
// session works the same (to its 0.2 deg). How close the joints come, as their own sensors read them, is
// joint_loop_test.cpp's JointLoopCanSim.
TEST(CanHeadOverVirtualBus, WithBacklashOnTheNeckAndTiltTheDriverReadsTheJointsAtTheirTargets) {
  testing::TempBusDir dir;
  testing::run_head_session("virtual:session", dir.path(),
                            {"--backlash", "neck_pitch=1", "--backlash", "neck_roll=1", "--backlash", "neck_yaw=1",
                             "--backlash", "eyes_tilt=1"});
}

// Inside the test VM (make test-can-vm): the same session over the kernel's vcan0, logs kept in
// ROBOGENE_CAN_LOG_DIR.
TEST(CanHeadOverSocketCan, CanSimProcessAndDriverMoveEveryJoint) {
  const std::string iface = testing::vcan_or_skip();
  if (iface.empty()) GTEST_SKIP() << testing::kSkipReason;
  const char* logs = std::getenv("ROBOGENE_CAN_LOG_DIR");
  ASSERT_NE(logs, nullptr) << "set ROBOGENE_CAN_LOG_DIR";
  testing::run_head_session("socketcan:" + iface, logs);
}

// `robogene can-sim` with a bad config: exit status 1 and the field named.
TEST(CanSimCli, ABadConfigIsNamedAndTheExitStatusIsOne) {
  testing::TempBusDir dir;
  const std::string bad = dir.path() + "/bad.ini";
  {
    std::ifstream in(testing::head_ini_path());
    std::stringstream text;
    text << in.rdbuf();
    std::string ini = text.str();
    const auto at = ini.find("\naxis ");
    ini.replace(at + 1, ini.find('\n', at + 1) - at - 1, "axis 0 1 0 1 0 7");
    std::ofstream(bad) << ini;
  }
  const std::string cmd = testing::robogene_bin() + " can-sim --bus virtual:cli --from " + bad + " --duration 1 2>&1";
  FILE* p = ::popen(cmd.c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string out;
  char buf[512];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  const int status = ::pclose(p);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << out;
  EXPECT_NE(out.find("bad.ini:"), std::string::npos) << out;
  EXPECT_NE(out.find("[GENERAL] key 'axis': value 6 (7) is outside [0, 1]"), std::string::npos) << out;
}

// --backlash and --reverse-joint-encoder name motors: a joint no one motor drives, or a width that is not one, is a
// usage error (exit status 2) naming it.
TEST(CanSimCli, BacklashAndReversedEncodersNameMotors) {
  testing::TempBusDir dir;
  const auto run = [&](const std::string& options) {
    const std::string cmd = testing::robogene_bin() + " can-sim --bus virtual:cli --from " + testing::head_ini_path() +
                            " --duration 0.1 " + options + " 2>&1";
    FILE* p = ::popen(cmd.c_str(), "r");
    std::string out;
    char buf[512];
    while (p && std::fgets(buf, sizeof buf, p)) out += buf;
    const int status = p ? ::pclose(p) : -1;
    return std::make_pair(WIFEXITED(status) ? WEXITSTATUS(status) : -1, out);
  };
  auto [status, out] = run("--backlash eyes_version=1");
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find("--backlash eyes_version=1: 'eyes_version' is no motor of"), std::string::npos) << out;
  EXPECT_NE(out.find("left_eye_pan, right_eye_pan"), std::string::npos) << out;
  std::tie(status, out) = run("--backlash neck_yaw=-0.5");
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find("'-0.5' is not a width in degrees >= 0"), std::string::npos) << out;
  std::tie(status, out) = run("--reverse-joint-encoder neck");
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find("--reverse-joint-encoder neck: 'neck' is no motor of"), std::string::npos) << out;
  std::tie(status, out) = run("--backlash neck_yaw=1 --backlash left_eye_pan=2 --reverse-joint-encoder neck_pitch");
  EXPECT_EQ(status, 0) << out;
  EXPECT_NE(out.find("backlash neck_yaw=1 deg; backlash left_eye_pan=2 deg; neck_pitch's joint encoder reversed"),
            std::string::npos) << out;
}

}  // namespace
}  // namespace robogene::can
