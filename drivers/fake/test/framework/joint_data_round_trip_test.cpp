// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// decode_joint_data reads back what encode_joint_data wrote from test_motor, with the flags of
// the fields test_motor lacks.
#include <gtest/gtest.h>

#include "robogene/dev/generated/interfaces.hpp"
#include "robogene/dev/joint_data.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/dev/simulation_clock.hpp"

using namespace robogene;
using namespace robogene::dev;

TEST(JointDataDecode, ReadsBackWhatTheEncoderWritesFlagsIncluded) {
  PolyDriver device(Property::from_command_line({"--device", "test_motor", "--axes", "2", "--clock", "manual"}));
  DeviceDriver* driver = nullptr;
  IEncoders* enc = nullptr;
  IVelocityControl* vel = nullptr;
  ISimulationClock* clock = nullptr;
  ASSERT_TRUE(device.view(driver) && device.view(enc) && device.view(vel) && device.view(clock));
  ASSERT_TRUE(enc->setEncoders({10.0, -20.0}));
  ASSERT_TRUE(vel->velocityMove(1, 5.0));
  ASSERT_TRUE(clock->advance(0.05));  // mid-ramp: speed 2.5 deg/s, acceleration 50 deg/s^2
  Bottle message;
  ASSERT_TRUE(encode_joint_data(*driver, message));
  const JointData d = decode_joint_data(message);
  std::vector<double> pos, speeds, accs;
  ASSERT_TRUE(enc->getEncoders(pos) && enc->getEncoderSpeeds(speeds) && enc->getEncoderAccelerations(accs));
  EXPECT_EQ(d.position.values, pos);
  EXPECT_EQ(d.velocity.values, speeds);
  EXPECT_EQ(d.acceleration.values, accs);
  EXPECT_NEAR(speeds[1], 2.5, 1e-9);
  EXPECT_TRUE(d.position.valid && d.velocity.valid && d.acceleration.valid && d.torque.valid);
  EXPECT_FALSE(d.motor_position.valid || d.pwm.valid || d.current.valid || d.interaction_mode.valid);
  EXPECT_EQ(d.control_mode.values, (std::vector<std::int32_t>{static_cast<std::int32_t>(ControlMode::position),
                                                              static_cast<std::int32_t>(ControlMode::velocity)}));
}
