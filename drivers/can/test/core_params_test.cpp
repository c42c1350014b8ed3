// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The simulated boards run with what the board images run with: the core parameters the simulator
// derives from head.ini equal those the firmware takes from its generated table
// (robogene_head_board_config.h), board by board.
#include <gtest/gtest.h>

#include "../src/sim/core_params.hpp"
#include "head_config_fixture.hpp"
#include "rg_board_config.h"

namespace robogene::can::sim {
namespace {

void expect_same_axis(const rg_axis_params_t& sim, const rg_axis_params_t& fw, const std::string& what) {
  EXPECT_EQ(sim.present, fw.present) << what;
  EXPECT_EQ(sim.min_position, fw.min_position) << what;
  EXPECT_EQ(sim.max_position, fw.max_position) << what;
  EXPECT_EQ(sim.max_speed, fw.max_speed) << what;
  EXPECT_EQ(sim.current_limit_ma, fw.current_limit_ma) << what;
  EXPECT_EQ(sim.has_brake, fw.has_brake) << what;
  EXPECT_EQ(sim.pid.kp, fw.pid.kp) << what;
  EXPECT_EQ(sim.pid.ki, fw.pid.ki) << what;
  EXPECT_EQ(sim.pid.kd, fw.pid.kd) << what;
  EXPECT_EQ(sim.pid.shift, fw.pid.shift) << what;
  EXPECT_EQ(sim.pid.offset, fw.pid.offset) << what;
  EXPECT_EQ(sim.pid.output_limit, fw.pid.output_limit) << what;
  EXPECT_EQ(sim.pid.integral_limit, fw.pid.integral_limit) << what;
  EXPECT_EQ(sim.homing.direction, fw.homing.direction) << what;
  EXPECT_EQ(sim.homing.speed, fw.homing.speed) << what;
  EXPECT_EQ(sim.homing.pwm_limit, fw.homing.pwm_limit) << what;
  EXPECT_EQ(sim.homing.stop_position, fw.homing.stop_position) << what;
  EXPECT_EQ(sim.homing.backoff, fw.homing.backoff) << what;
  EXPECT_EQ(sim.homing.timeout_ms, fw.homing.timeout_ms) << what;
  EXPECT_EQ(sim.homing.current_limit_ma, fw.homing.current_limit_ma) << what;
}

TEST(CoreParams, TheSimulatorRunsEachBoardWithItsFirmwareImagesNumbers) {
  const HeadConfig head = testing::head_config();
  ASSERT_EQ(head.boards.size(), 3u);
  for (const auto& b : head.boards) {
    const rg_board_params_t sim = core_params(head, b);
    rg_board_params_t fw{};
    ASSERT_TRUE(rg_board_params_for_address(static_cast<std::uint8_t>(b.address), &fw)) << b.name;
    EXPECT_EQ(sim.address, fw.address) << b.name;
    EXPECT_EQ(sim.coupling, fw.coupling) << b.name;
    for (int r = 0; r < 2; ++r) {
      for (int m = 0; m < 2; ++m) EXPECT_EQ(sim.counts_m2a[r][m], fw.counts_m2a[r][m]) << b.name;
    }
    EXPECT_EQ(sim.pwm_full_scale, fw.pwm_full_scale);
    EXPECT_EQ(sim.control_period_us, fw.control_period_us);
    EXPECT_EQ(sim.velocity_timeout_ms, fw.velocity_timeout_ms);
    EXPECT_EQ(sim.protocol_major, fw.protocol_major);
    EXPECT_EQ(sim.protocol_minor, fw.protocol_minor);
    EXPECT_EQ(sim.broadcast_policy, fw.broadcast_policy);
    for (int a = 0; a < 2; ++a) expect_same_axis(sim.axes[a], fw.axes[a], b.name + " axis " + std::to_string(a));
  }
  rg_board_params_t none{};
  EXPECT_FALSE(rg_board_params_for_address(9, &none)) << "the head has no board 9";
}

TEST(CoreParams, ACouplingTheFirmwareDoesNotImplementIsRefused) {
  HeadConfig head = testing::head_config();
  BoardConfig eyes = *head.board(3);
  eyes.coupling->j2m = {{{1.0, 1.0}, {1.0, -1.0}}};
  EXPECT_THROW(core_params(head, eyes), Error);
}

}  // namespace
}  // namespace robogene::can::sim
