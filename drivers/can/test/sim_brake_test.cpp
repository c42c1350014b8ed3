// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The simulated boards' holding brakes (pitch and roll carry one, brake in head.ini): commanded over
// the protocol, the firmware's brake sequence reaches a brake model that locks its motor. Released only
// once the bridge has held for a period; applied while the bridge is still on when the axis is
// disabled, faults, loses its supply or the board enters its bootloader; applied from power-up. A
// braked motor does not turn; the axes without a brake move as before.
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "../src/driver/robogene_can.hpp"
#include "board_sim_rig.hpp"
#include "head_rig.hpp"
#include "rg_boot.h"
#include "robogene/can/sim/simulated_head.hpp"
#include "robogene/can/virtual_bus.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/log.hpp"
#include "test_bus_dir.hpp"

namespace robogene::can::sim {
namespace {

using testing::Rig;

constexpr int kPitch = 0, kRoll = 1, kYaw = 2;

// Enables an axis in position mode and runs until its brake has released.
void enable(Rig& rig, int joint) {
  rig.to_joint(joint, SetControlMode{ControlMode::position});
  rig.run(0.05);
}

// Velocity commands refreshed every 20 ms for `seconds`, as the driver sends them.
void drive_at(Rig& rig, int joint, double deg_per_s, double seconds) {
  const JointConfig& jc = rig.head.joints[static_cast<std::size_t>(joint)];
  const auto speed = std::round(deg_per_s * jc.counts_per_degree / 10) * 10;
  const auto acc = std::round(500 * jc.counts_per_degree / 1000) * 1000;
  for (int k = 0; k < static_cast<int>(seconds / 0.02); ++k) {
    rig.to_joint(joint, VelocityMove{speed, acc});
    rig.run(0.02);
  }
}

TEST(SimBrake, TheConfiguredAxesHaveBrakesAppliedFromPowerUp) {
  Rig rig;
  BoardSim& neck = rig.board_of(kPitch);
  EXPECT_TRUE(neck.has_brake(0) && neck.has_brake(1)) << "pitch and roll carry brakes (head.ini brake)";
  EXPECT_TRUE(neck.brake_holding(0) && neck.brake_holding(1));
  rig.run(0.1);
  EXPECT_TRUE(neck.brake_holding(0) && neck.brake_holding(1)) << "idle axes stay braked";
  EXPECT_TRUE(neck.take_brake_changes().empty());
}

TEST(SimBrake, EnablingReleasesTheBrakeOnlyAfterTheBridgeHeldForAPeriod) {
  Rig rig;
  BoardSim& neck = rig.board_of(kPitch);
  rig.to_joint(kPitch, SetControlMode{ControlMode::position});
  rig.run(0.001);
  EXPECT_TRUE(neck.brake_holding(0)) << "the first period with the bridge on: the brake still holds";
  EXPECT_TRUE(neck.take_brake_changes().empty());
  rig.run(0.001);
  EXPECT_FALSE(neck.brake_holding(0));
  const auto changes = neck.take_brake_changes();
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0].motor, 0);
  EXPECT_TRUE(changes[0].released);
  EXPECT_TRUE(changes[0].bridge_on);
  EXPECT_EQ(changes[0].bridge_periods, 1u) << "released in the second period of the bridge holding";
  EXPECT_TRUE(neck.brake_holding(1)) << "roll, not enabled, keeps its brake";
}

TEST(SimBrake, DisablingAppliesTheBrakeBeforeTheBridgeStops) {
  Rig rig;
  BoardSim& neck = rig.board_of(kPitch);
  enable(rig, kPitch);
  ASSERT_FALSE(neck.brake_holding(0));
  neck.take_brake_changes();
  rig.to_joint(kPitch, SetControlMode{ControlMode::idle});
  rig.run(0.001);
  EXPECT_TRUE(neck.brake_holding(0));
  const auto changes = neck.take_brake_changes();
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_FALSE(changes[0].released);
  EXPECT_TRUE(changes[0].bridge_on) << "the brake takes the joint while the bridge still holds it";
  rig.run(0.2);
  EXPECT_TRUE(neck.brake_holding(0));
  EXPECT_TRUE(neck.take_brake_changes().empty());
}

// Each fault the firmware detects stops a running axis: the brake applies in that period while the
// bridge is still on, and stays applied until the host clears the fault and enables the axis again.
class SimBrakeFault : public ::testing::TestWithParam<int> {};

TEST_P(SimBrakeFault, AppliesTheBrakeBeforeTheBridgeStops) {
  Rig rig;
  BoardSim& neck = rig.board_of(kPitch);
  enable(rig, kPitch);
  neck.take_brake_changes();
  switch (GetParam()) {
    case 0: neck.set_supply_voltage(7.5); break;   // undervoltage
    case 1: neck.set_supply_voltage(20.0); break;  // overvoltage
    case 2: neck.set_bridge_fault(true); break;    // the drivers' nFAULT
  }
  EXPECT_FALSE(neck.brake_holding(0)) << "the brake follows the firmware, not the fault line";
  rig.run(0.001);
  ASSERT_EQ(neck.mode(0), ControlMode::hardware_fault);
  EXPECT_TRUE(neck.brake_holding(0));
  const auto changes = neck.take_brake_changes();
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_FALSE(changes[0].released);
  EXPECT_TRUE(changes[0].bridge_on);
  neck.set_supply_voltage(12.0);
  neck.set_bridge_fault(false);
  rig.run(0.1);
  EXPECT_TRUE(neck.brake_holding(0)) << "a latched fault keeps the brake applied";
  rig.to_joint(kPitch, SetControlMode{ControlMode::force_idle});
  rig.run(0.1);
  EXPECT_TRUE(neck.brake_holding(0)) << "idle after the fault: still applied";
  enable(rig, kPitch);
  EXPECT_FALSE(neck.brake_holding(0)) << "enabled again: released";
}

INSTANTIATE_TEST_SUITE_P(Faults, SimBrakeFault, ::testing::Values(0, 1, 2));

TEST(SimBrake, WithoutSupplyTheBrakeHoldsAtOnceAndTheJointStopsDeadWhileCommanded) {
  Rig rig;
  BoardSim& neck = rig.board_of(kPitch);
  BoardSim& yaw_board = rig.board_of(kYaw);
  rig.to_joint(kPitch, SetControlMode{ControlMode::velocity});
  rig.to_joint(kYaw, SetControlMode{ControlMode::velocity});
  for (int k = 0; k < 25; ++k) {  // both joints at 20 deg/s
    for (int j : {kPitch, kYaw}) {
      const JointConfig& jc = rig.head.joints[static_cast<std::size_t>(j)];
      rig.to_joint(j, VelocityMove{std::round(20 * jc.counts_per_degree / 10) * 10,
                                   std::round(500 * jc.counts_per_degree / 1000) * 1000});
    }
    rig.run(0.02);
  }
  ASSERT_GT(rig.board_of(kPitch).motor_degrees(0), 5.0);
  neck.take_brake_changes();
  neck.set_supply_voltage(0.0);
  yaw_board.set_supply_voltage(0.0);
  EXPECT_TRUE(neck.brake_holding(0)) << "a spring-applied brake holds the moment its coil loses supply";
  const auto changes = neck.take_brake_changes();
  ASSERT_EQ(changes.size(), 1u) << "pitch's brake was released, roll's held already";
  EXPECT_FALSE(changes[0].released);
  EXPECT_TRUE(changes[0].bridge_on);
  const double pitch_at_cut = neck.motor_degrees(0), yaw_at_cut = yaw_board.motor_degrees(0);
  drive_at(rig, kPitch, 20.0, 0.5);  // the host keeps commanding
  EXPECT_EQ(neck.motor_degrees(0), pitch_at_cut) << "braked: not a step further";
  EXPECT_GT(std::fabs(yaw_board.motor_degrees(0) - yaw_at_cut), 0.05) << "yaw has no brake: it runs on";
}

TEST(SimBrake, EnteringTheBootloaderAppliesTheBrakeAndItStaysApplied) {
  Rig rig;
  BoardSim& neck = rig.board_of(kPitch);
  enable(rig, kPitch);
  enable(rig, kRoll);
  neck.take_brake_changes();
  rig.send(1, 0, EnterBootloader{RG_BOOT_ENTER_KEY});
  ASSERT_TRUE(neck.in_bootloader());
  EXPECT_TRUE(neck.brake_holding(0) && neck.brake_holding(1));
  const auto changes = neck.take_brake_changes();
  ASSERT_EQ(changes.size(), 2u);
  for (const auto& c : changes) {
    EXPECT_FALSE(c.released);
    EXPECT_TRUE(c.bridge_on) << "applied by the firmware before it turned the bridge off";
  }
  rig.run(0.5);
  EXPECT_TRUE(neck.brake_holding(0) && neck.brake_holding(1)) << "the bootloader never drives the gates";
}

TEST(SimBrake, APowerCycleStartsWithTheBrakesApplied) {
  Rig rig;
  BoardSim& neck = rig.board_of(kPitch);
  enable(rig, kPitch);
  ASSERT_FALSE(neck.brake_holding(0));
  neck.power_cycle();
  EXPECT_TRUE(neck.brake_holding(0));
  rig.run(0.1);
  EXPECT_TRUE(neck.brake_holding(0));
  EXPECT_EQ(neck.mode(0), ControlMode::idle);
}

TEST(SimBrake, AxesWithoutABrakeAreUnaffected) {
  Rig rig;
  for (int j : {kYaw, 4}) {  // neck-yaw-eyes-tilt and the coupled eye board: no brakes
    BoardSim& b = rig.board_of(j);
    for (int m = 0; m < 2; ++m) {
      EXPECT_FALSE(b.has_brake(m));
      EXPECT_FALSE(b.brake_holding(m));
    }
  }
  const JointConfig& yaw = rig.head.joints[kYaw];
  rig.to_joint(kYaw, SetControlMode{ControlMode::position});
  rig.to_joint(kYaw, PositionMove{static_cast<std::int32_t>(std::lround(15 * yaw.counts_per_degree)),
                                  std::round(30 * yaw.counts_per_degree / 10) * 10});
  rig.run(0.2);
  EXPECT_GT(rig.degrees(kYaw), 2.0) << "it moves in its first periods: there is no brake to wait for";
  rig.run(1.5);
  EXPECT_NEAR(rig.degrees(kYaw), 15.0, 0.1);
  rig.board_of(kYaw).set_bridge_fault(true);
  rig.run(0.01);
  rig.to_joint(kYaw, SetControlMode{ControlMode::idle});
  rig.run(0.01);
  EXPECT_FALSE(rig.board_of(kYaw).brake_holding(0));
  EXPECT_TRUE(rig.board_of(kYaw).take_brake_changes().empty());
  EXPECT_TRUE(rig.board_of(4).take_brake_changes().empty());
}

TEST(SimBrake, TheMotorModelHoldsUnderFullDriveWhileBraked) {
  DcMotor motor;
  motor.set_braked(true);
  for (int i = 0; i < 1000; ++i) motor.step(i % 2 ? 1.0 : -1.0, 0.001);
  for (int i = 0; i < 1000; ++i) motor.step(1.0, 0.001);
  EXPECT_EQ(motor.joint_degrees(), 0.0);
  EXPECT_EQ(motor.joint_degrees_per_second(), 0.0);
  EXPECT_NEAR(motor.current_amps(), motor.parameters().bridge_current_limit, 1e-9) << "stall current flows";
  motor.set_braked(false);
  for (int i = 0; i < 100; ++i) motor.step(1.0, 0.001);
  EXPECT_GT(motor.joint_degrees(), 1.0);
}

// Over the bus with the real driver, which puts every axis in position mode when it opens: `robogene
// can-sim` users see each brake change in the log, naming the board and the joint.
TEST(SimBrake, TheSimulatedHeadLogsEachChangeNamingTheBoardAndJoint) {
  ::robogene::can::testing::TempBusDir dir;
  std::mutex lock;
  std::vector<std::string> lines;
  const log::Level before = log::level();
  log::set_level(log::Level::Info);
  log::set_sink([&](log::Level, std::string_view, std::string_view text) {
    std::lock_guard<std::mutex> g(lock);
    lines.emplace_back(text);
  });
  auto seen = [&](const std::string& what) {
    std::lock_guard<std::mutex> g(lock);
    for (const auto& l : lines) {
      if (l.find(what) != std::string::npos) return true;
    }
    return false;
  };
  {
    const HeadConfig head = ::robogene::can::testing::head_config();
    SimulatedHead sim(head, std::make_unique<VirtualBus>("brakes"));
    EXPECT_TRUE(sim.has_brake(1, 0) && sim.has_brake(1, 1));
    EXPECT_FALSE(sim.has_brake(2, 0) || sim.has_brake(2, 1) || sim.has_brake(3, 0) || sim.has_brake(3, 1));
    EXPECT_TRUE(sim.brake_holding(1, 0) && sim.brake_holding(1, 1));
    dev::PolyDriver device;
    ASSERT_TRUE(device.open(::robogene::can::testing::driver_config("virtual:brakes"))) << device.last_error();
    dev::IControlMode* mode = nullptr;
    ASSERT_TRUE(device.view(mode));
    EXPECT_TRUE(::robogene::can::testing::eventually(2.0, [&] { return !sim.brake_holding(1, 0) && !sim.brake_holding(1, 1); }));
    for (const char* joint : {"neck_pitch", "neck_roll"}) {
      EXPECT_TRUE(::robogene::can::testing::eventually(2.0, [&] {
        return seen(std::string("simulated board 1 (neck-pitch-roll) ") + joint + ": brake released, its bridge on for 1 period");
      })) << joint;
    }
    ASSERT_TRUE(mode->setControlMode(kPitch, dev::ControlMode::idle));
    EXPECT_TRUE(::robogene::can::testing::eventually(2.0, [&] { return sim.brake_holding(1, 0); }));
    EXPECT_TRUE(::robogene::can::testing::eventually(
        2.0, [&] { return seen("simulated board 1 (neck-pitch-roll) neck_pitch: brake applied, its bridge still on"); }));
    EXPECT_FALSE(sim.brake_holding(1, 1)) << "roll stays enabled, its brake released";
    EXPECT_FALSE(seen("neck_roll: brake applied"));
    EXPECT_FALSE(seen("neck_yaw") || seen("eyes_")) << "the axes without a brake log none";
    device.close();
  }
  log::set_sink({});
  log::set_level(before);
}

}  // namespace
}  // namespace robogene::can::sim
