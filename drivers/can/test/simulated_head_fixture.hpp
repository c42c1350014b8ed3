// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The fixture of the tests that drive the joints over the bus: a simulated head on a virtual bus of the test's
// own, and the robogene_can driver opened on it by open() (after the test has set the head up).
#pragma once

#include <memory>

#include <gtest/gtest.h>

#include "../src/driver/robogene_can.hpp"
#include "head_rig.hpp"
#include "robogene/can/sim/simulated_head.hpp"
#include "robogene/can/virtual_bus.hpp"
#include "test_bus_dir.hpp"

namespace robogene::can::testing {

class SimulatedHeadOverBus : public ::testing::Test {
 protected:
  void SetUp() override {
    head_ = head_config();
    sim_ = std::make_unique<sim::SimulatedHead>(head_, std::make_unique<VirtualBus>("head"));
  }
  void TearDown() override {
    driver_.close();
    sim_.reset();
  }
  void open() { ASSERT_TRUE(driver_.open(driver_config("virtual:head"))) << driver_.last_error(); }

  TempBusDir dir_;
  HeadConfig head_;
  std::unique_ptr<sim::SimulatedHead> sim_;
  RobogeneCan driver_;
};

}  // namespace robogene::can::testing
