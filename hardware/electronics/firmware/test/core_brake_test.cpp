// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The holding brakes' outputs (board revision D): applied from reset, released only once the bridge
// has been on and holding for a period, applied before the bridge turns off on a disable, on every
// fault and on enter_bootloader, and never driven for an axis without a brake.
#include <gtest/gtest.h>

#include <algorithm>

#include "fake_board.hpp"
#include "rg_boot.h"

namespace rg_test {
namespace {

void set_mode(FakeBoard& b, unsigned axis, std::uint8_t mode) { b.command({ROBOGENE_CAN_CMD_SET_CONTROL_MODE, mode}, axis); }

// Index of the first call of `kind` for `motor` with `on`, at or after `from`; -1 when there is none.
long first(const FakeBoard& b, OutputCall::Kind kind, unsigned motor, bool on, std::size_t from = 0) {
  for (std::size_t i = from; i < b.outputs.size(); ++i) {
    const auto& o = b.outputs[i];
    if (o.kind == kind && o.motor == motor && o.on == on) return static_cast<long>(i);
  }
  return -1;
}

void tick(FakeBoard& b) { b.run(0.001); }

struct BrakedBoard : FakeBoard {
  BrakedBoard() {
    params.axes[0].has_brake = true;  // axis 1 has none
  }
};

TEST(CoreBrake, AppliedAtStartAndNeverDrivenForAnAxisWithoutBrake) {
  BrakedBoard b;
  b.start();
  EXPECT_EQ(b.brake_writes[0], 1);
  EXPECT_FALSE(b.brake_released[0]);
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  set_mode(b, 1, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.command(position_move(3000, 2000), 1);
  b.run(0.5);
  EXPECT_TRUE(b.brake_released[0]);
  EXPECT_EQ(b.brake_writes[1], 0) << "axis 1 has no brake: its pin is never driven";
  EXPECT_NEAR(b.core.axes[1].measured, 3000, 20) << "and it moves all the same";
}

TEST(CoreBrake, ReleasedOnlyAfterTheBridgeHeldForAPeriod) {
  BrakedBoard b;
  b.start();
  b.run(0.01);
  EXPECT_FALSE(b.brake_released[0]) << "idle: the brake holds";
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.outputs.clear();
  tick(b);
  EXPECT_TRUE(b.plant[0].enabled);
  EXPECT_FALSE(b.brake_released[0]) << "the first enabled period: the loop holds, the brake still too";
  tick(b);
  EXPECT_TRUE(b.brake_released[0]);
  const long bridge_on = first(b, OutputCall::kBridge, 0, true);
  const long released = first(b, OutputCall::kBrake, 0, true);
  ASSERT_GE(bridge_on, 0);
  ASSERT_GE(released, 0);
  EXPECT_LT(bridge_on, released);
  EXPECT_EQ(first(b, OutputCall::kBrake, 0, false, static_cast<std::size_t>(released)), -1);
}

TEST(CoreBrake, AppliedBeforeTheBridgeTurnsOffOnDisable) {
  BrakedBoard b;
  b.start();
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.run(0.05);
  ASSERT_TRUE(b.brake_released[0]);
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_IDLE);
  b.outputs.clear();
  tick(b);
  EXPECT_FALSE(b.brake_released[0]);
  EXPECT_FALSE(b.plant[0].enabled);
  const long applied = first(b, OutputCall::kBrake, 0, false);
  const long bridge_off = first(b, OutputCall::kBridge, 0, false);
  ASSERT_GE(applied, 0);
  ASSERT_GE(bridge_off, 0);
  EXPECT_LT(applied, bridge_off) << "the brake takes the load before the bridge lets go";
  b.run(0.1);
  EXPECT_FALSE(b.brake_released[0]);
}

// Each fault the core detects stops a running axis: the brake applies in the same period, before the
// bridge turns off, and stays applied until the host clears the fault and enables the axis again.
class CoreBrakeFault : public ::testing::TestWithParam<int> {};

TEST_P(CoreBrakeFault, AppliedBeforeTheBridgeTurnsOff) {
  BrakedBoard b;
  b.start();
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.run(0.05);
  ASSERT_TRUE(b.brake_released[0]);
  switch (GetParam()) {
    case 0: b.supply = 8000; break;                    // undervoltage
    case 1: b.supply = 20000; break;                   // overvoltage
    case 2: b.fault = true; break;                     // the drivers' nFAULT
    case 3: b.plant[0].forced_current_ma = 5000; break;  // over 150 % of the 1 A limit
  }
  b.outputs.clear();
  for (int i = 0; i < 30 && b.mode(0) != ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT; ++i) tick(b);
  ASSERT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT);
  const long applied = first(b, OutputCall::kBrake, 0, false);
  const long bridge_off = first(b, OutputCall::kBridge, 0, false);
  ASSERT_GE(applied, 0);
  ASSERT_GE(bridge_off, 0);
  EXPECT_LT(applied, bridge_off);
  EXPECT_FALSE(b.brake_released[0]);
  b.supply = 12000;
  b.fault = false;
  b.plant[0].forced_current_ma.reset();
  b.run(0.1);
  EXPECT_FALSE(b.brake_released[0]) << "a latched fault keeps the brake applied";
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_FORCE_IDLE);
  b.run(0.05);
  EXPECT_FALSE(b.brake_released[0]) << "force_idle clears the fault; idle still holds on the brake";
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.run(0.05);
  EXPECT_TRUE(b.brake_released[0]);
}

INSTANTIATE_TEST_SUITE_P(Core, CoreBrakeFault, ::testing::Values(0, 1, 2, 3));

TEST(CoreBrake, AppliedBeforeTheBridgesTurnOffForTheBootloader) {
  FakeBoard b;
  b.params.axes[0].has_brake = b.params.axes[1].has_brake = true;
  b.start();
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  set_mode(b, 1, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.run(0.05);
  ASSERT_TRUE(b.brake_released[0] && b.brake_released[1]);
  b.outputs.clear();
  b.command(le32(ROBOGENE_CAN_CMD_ENTER_BOOTLOADER, RG_BOOT_ENTER_KEY), 0, 1, ROBOGENE_CAN_CLASS_BOOTLOADER);
  EXPECT_EQ(b.bootloader_requests, 1);
  for (unsigned m = 0; m < 2u; ++m) {
    EXPECT_FALSE(b.brake_released[m]);
    const long applied = first(b, OutputCall::kBrake, m, false);
    const long bridge_off = first(b, OutputCall::kBridge, m, false);
    ASSERT_GE(applied, 0);
    ASSERT_GE(bridge_off, 0);
    EXPECT_LT(applied, bridge_off) << "motor " << m;
  }
}

TEST(CoreBrake, ACoupledBoardNeverDrivesTheBrakeOutputs) {
  FakeBoard b(RG_COUPLING_VERSION_VERGENCE);
  b.params.axes[0].has_brake = b.params.axes[1].has_brake = true;
  b.start();
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.run(0.1);
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_IDLE);
  b.run(0.1);
  EXPECT_EQ(b.brake_writes[0] + b.brake_writes[1], 0);
}

TEST(CoreBrake, AHalWithoutBrakeOutputsRunsTheBrakedAxisAnyway) {
  BrakedBoard b;
  b.hal.set_brake = nullptr;  // the simulator, a board before revision D
  b.start();
  set_mode(b, 0, ROBOGENE_CAN_CONTROL_MODE_POSITION);
  b.command(position_move(3000, 2000));
  b.run(0.5);
  EXPECT_NEAR(b.core.axes[0].measured, 3000, 20);
  EXPECT_EQ(b.brake_writes[0], 0);
}

}  // namespace
}  // namespace rg_test
