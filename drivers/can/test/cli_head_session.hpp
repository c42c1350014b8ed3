// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A whole head session across processes: `robogene can-sim` simulates the boards on a bus, the
// robogene_can driver in this process moves every joint through position and velocity commands,
// and both sides write candump logs, which are read back. Used on the virtual bus here and on
// real SocketCAN (vcan0) inside the test VM.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "head_rig.hpp"
#include "motor_control.hpp"
#include "robogene/can/candump_log.hpp"
#include "robogene/dev/generated/iencoders.hpp"
#include "robogene/dev/generated/ipositioncontrol.hpp"
#include "robogene/dev/generated/ivelocitycontrol.hpp"
#include "robogene/dev/poly_driver.hpp"

namespace robogene::can::testing {

inline std::string robogene_bin() {
  const char* bin = std::getenv("ROBOGENE_BIN");
  return bin && *bin ? bin : std::string(ROBOGENE_BINARY_DIR) + "/bin/robogene";
}

// Starts `robogene can-sim`; the caller stops it with SIGTERM.
// `pose`: can-sim's --pose (the joints' angles at power-up), or "" for all at 0; `extra`: more of its options
// (--backlash JOINT=DEG, --reverse-joint-encoder JOINT).
inline pid_t start_simulator(const std::string& bus, const std::string& log, const std::string& pose = "",
                             const std::vector<std::string>& extra = {}) {
  std::vector<std::string> words = {robogene_bin(), "can-sim", "--bus", bus, "--from", head_ini_path(), "--log", log,
                                    "--duration", "120"};
  if (!pose.empty()) words.insert(words.end(), {"--pose", pose});
  words.insert(words.end(), extra.begin(), extra.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

// Ends the simulator however the test leaves (a failed ASSERT returns early).
struct ChildGuard {
  pid_t pid;
  ~ChildGuard() {
    if (pid > 0) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, nullptr, 0);
    }
  }
};

// `sim_options`: more of can-sim's options (--backlash ...), the checks the same.
inline void run_head_session(const std::string& bus, const std::string& log_dir,
                             const std::vector<std::string>& sim_options = {}) {
  const std::string sim_log = log_dir + "/can-sim.log", driver_log = log_dir + "/robogene_can.log";
  // The neck and the eye tilt power up away from 0: their boards home them from their joint encoders, so
  // the driver reads this pose from the start (the eyes, homed against stops by can-home, count from 0).
  const std::vector<std::pair<std::string, double>> pose = {{"neck_pitch", 12.0}, {"neck_roll", -7.5}, {"neck_yaw", 20.0},
                                                            {"eyes_tilt", -10.0}};
  std::string pose_arg;
  for (const auto& [name, deg] : pose) pose_arg += (pose_arg.empty() ? "" : ",") + name + "=" + std::to_string(deg);
  ChildGuard sim_guard{start_simulator(bus, sim_log, pose_arg, sim_options)};
  const pid_t sim = sim_guard.pid;
  ASSERT_GT(sim, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // let it open the bus
  const HeadConfig head = head_config();
  {
    dev::Property config = driver_config(bus);
    config.put("can_log", Value(driver_log));
    dev::PolyDriver device;
    bool opened = false;
    // The simulator may still be starting (a slow VM): try for a few seconds.
    eventually(10.0, [&] { return opened = device.open(config); });
    ASSERT_TRUE(opened) << device.last_error();
    dev::IEncoders* enc = nullptr;
    dev::IPositionControl* pos = nullptr;
    dev::IVelocityControl* vel = nullptr;
    ASSERT_TRUE(device.view(enc) && device.view(pos) && device.view(vel));
    for (std::size_t j = 0; j < head.joints.size(); ++j) {
      double expected = 0.0;
      for (const auto& [name, deg] : pose) expected = name == head.joints[j].name ? deg : expected;
      double v = 1e9;
      ASSERT_TRUE(eventually(2.0, [&] { return enc->getEncoder(static_cast<int>(j), v); }));
      EXPECT_NEAR(v, expected, 0.05) << head.joints[j].name << " at power-up";
    }
    std::vector<double> targets;
    for (const auto& j : head.joints) targets.push_back(j.min + 0.7 * (j.max - j.min));
    ASSERT_TRUE(pos->setRefSpeeds(std::vector<double>(head.joints.size(), 40.0)));
    ASSERT_TRUE(pos->positionMove(targets));
    ASSERT_TRUE(eventually(15.0, [&] {
      std::vector<double> at;
      if (!enc->getEncoders(at)) return false;
      for (std::size_t j = 0; j < at.size(); ++j) {
        if (std::fabs(at[j] - targets[j]) > 0.2) return false;
      }
      return true;
    })) << "the joints did not reach their targets";
    std::vector<double> at, later;
    ASSERT_TRUE(enc->getEncoders(at));
    std::vector<double> speeds(head.joints.size(), -8.0);
    for (std::size_t j = 0; j < speeds.size(); ++j) {
      if (targets[j] < 0) speeds[j] = 8.0;
    }
    ASSERT_TRUE(vel->velocityMove(speeds));
    ASSERT_TRUE(eventually(15.0, [&] {
      if (!enc->getEncoders(later)) return false;
      for (std::size_t j = 0; j < later.size(); ++j) {
        if ((later[j] - at[j]) * speeds[j] < 4.0 * 8.0) return false;  // 4 degrees the commanded way
      }
      return true;
    })) << "velocity moves did not move every joint";
    ASSERT_TRUE(pos->stop());
    device.close();
  }
  ::kill(sim, SIGTERM);
  int status = 0;
  ASSERT_EQ(::waitpid(sim, &status, 0), sim);
  sim_guard.pid = 0;
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "can-sim exit status " << status;

  // Both logs are candump's format and hold what each side saw.
  std::map<std::string, int> sim_seen, driver_seen;
  for (const auto& e : read_candump_log(sim_log)) {
    if (e.frame) ++sim_seen[message_name(decode(*e.frame).message)];
  }
  for (const auto& e : read_candump_log(driver_log)) {
    if (e.frame) ++driver_seen[message_name(decode(*e.frame).message)];
  }
  EXPECT_GE(sim_seen["position_move"], static_cast<int>(head.joints.size()));
  EXPECT_GE(sim_seen["velocity_move"], static_cast<int>(head.joints.size()));
  EXPECT_GT(sim_seen["position_broadcast"], 100);
  EXPECT_GT(driver_seen["position_broadcast"], 100);
  EXPECT_GE(driver_seen["get_firmware_version_reply"], static_cast<int>(head.boards.size()));
}

}  // namespace robogene::can::testing
