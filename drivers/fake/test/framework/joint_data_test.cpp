// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include "robogene/testing/vector_cases.hpp"

#include "robogene/testing/captured_joint_data.hpp"

#include "robogene/dev/generated/interfaces.hpp"
#include "robogene/dev/joint_data.hpp"
#include "robogene/dev/poly_driver.hpp"

using namespace robogene;
using namespace robogene::dev;

namespace {


}  // namespace

TEST(JointData, LayoutMatchesYarpsAndFieldsTestMotorLacksAreInvalid) {
  PolyDriver device(Property::from_command_line({"--device", "test_motor", "--clock", "manual"}));
  DeviceDriver* driver = nullptr;
  IEncoders* enc = nullptr;
  ASSERT_TRUE(device.view(driver) && device.view(enc));
  ASSERT_TRUE(enc->setEncoders({1.0, 2.0, 3.0, 4.0}));
  Bottle message;
  ASSERT_TRUE(encode_joint_data(*driver, message));
  ASSERT_EQ(message.size(), 22u);
  // The capture with test_motor's differences: no motor encoders, PWM, current or interaction
  // mode, so those are zeros flagged [fail] (09000000 6661696c); its torques are zero, at rest.
  std::string expected = test::kCapturedJointData;
  auto replace_field = [&](std::size_t field, const std::string& values) {
    // Each float64 field is 8 + 32 bytes of vector then 8 bytes of flag; find it by walking.
    const Bottle captured = Bottle::from_bytes([&] {
      std::vector<std::uint8_t> b;
      for (std::size_t i = 0; i + 1 < expected.size(); i += 2) {
        b.push_back(static_cast<std::uint8_t>(std::stoi(expected.substr(i, 2), nullptr, 16)));
      }
      return b;
    }());
    Bottle edited;
    for (std::size_t i = 0; i < captured.size(); ++i) {
      if (i == 2 * field) {
        edited.add(Bottle::from_text(values)[0]);
      } else if (i == 2 * field + 1) {
        edited.add(Value::vocab(vocab("fail")));
      } else {
        edited.add(captured[i]);
      }
    }
    expected = robogene::testing::to_hex(edited.to_bytes());
  };
  for (std::size_t field : {3u, 4u, 5u, 7u, 8u}) replace_field(field, "(0.0 0.0 0.0 0.0)");
  replace_field(10, "(0 0 0 0)");
  EXPECT_EQ(robogene::testing::to_hex(message.to_bytes()), expected);
  EXPECT_EQ(message.to_text(),
            "(1.0 2.0 3.0 4.0) [ok] (0.0 0.0 0.0 0.0) [ok] (0.0 0.0 0.0 0.0) [ok] "
            "(0.0 0.0 0.0 0.0) [fail] (0.0 0.0 0.0 0.0) [fail] (0.0 0.0 0.0 0.0) [fail] "
            "(0.0 0.0 0.0 0.0) [ok] (0.0 0.0 0.0 0.0) [fail] (0.0 0.0 0.0 0.0) [fail] "
            "(7565168 7565168 7565168 7565168) [ok] (0 0 0 0) [fail]");
}

TEST(JointData, ADeviceWithoutEncodersHasNoState) {
  PolyDriver device(Property::from_command_line({"--device", "fake_grabber", "--clock", "manual"}));
  DeviceDriver* driver = nullptr;
  ASSERT_TRUE(device.view(driver));
  Bottle message;
  EXPECT_FALSE(encode_joint_data(*driver, message));
}
