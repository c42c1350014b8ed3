// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// decode_joint_data: YARP 3.5's captured jointData and malformed messages, each refused with the
// item and field at fault (our own encoder's output read back: drivers/fake/test/framework/).
#include <gtest/gtest.h>

#include "robogene/testing/vector_cases.hpp"
#include "robogene/testing/captured_joint_data.hpp"

#include "robogene/dev/generated/interfaces.hpp"
#include "robogene/dev/joint_data.hpp"
#include "robogene/error.hpp"

using namespace robogene;
using namespace robogene::dev;

namespace {

std::string error_of(const std::string& text) {
  try {
    decode_joint_data(Bottle::from_text(text));
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// A well-formed two-axis message in text, with `field` (0-10) replaced by `replacement`.
std::string two_axes_with(std::size_t field, const std::string& replacement) {
  std::string out;
  for (std::size_t f = 0; f < 11; ++f) {
    if (f == field) {
      out += replacement + " ";
    } else {
      out += f >= 9 ? "(0 0) [ok] " : "(1.5 2.5) [ok] ";
    }
  }
  return out;
}

}  // namespace

TEST(JointDataDecode, ReadsYarp35sCapturedMessage) {
  const JointData d = decode_joint_data(Bottle::from_bytes(robogene::testing::from_hex(test::kCapturedJointData)));
  EXPECT_EQ(d.position.values, (std::vector<double>{1, 2, 3, 4}));
  EXPECT_TRUE(d.position.valid);
  EXPECT_EQ(d.velocity.values, (std::vector<double>{0, 0, 0, 0}));
  EXPECT_EQ(d.motor_position.values, (std::vector<double>{10, 20, 30, 40}));
  EXPECT_EQ(d.pwm.values, (std::vector<double>{33, 34, 35, 36}));
  EXPECT_EQ(d.current.values, (std::vector<double>{3300, 3400, 3500, 3600}));
  const auto pos = static_cast<std::int32_t>(vocab("pos"));
  EXPECT_EQ(d.control_mode.values, (std::vector<std::int32_t>{pos, pos, pos, pos}));
  EXPECT_TRUE(d.interaction_mode.valid);
}

TEST(JointDataDecode, MalformedMessagesNameTheItemAndTheField) {
  EXPECT_EQ(error_of("(1.0) [ok]"), "jointData has 2 items, expected 22 (11 fields, each followed by [ok] or [fail])");
  EXPECT_EQ(error_of(two_axes_with(0, "5.0 [ok]")), "jointData item 0 (jointPosition): expected a list of values, got 5.0");
  EXPECT_EQ(error_of(two_axes_with(1, "(1.0 \"x y\") [ok]")),
            "jointData item 2 (jointVelocity): value 1 is not a number: \"x y\"");
  EXPECT_EQ(error_of(two_axes_with(6, "(1.0 2.0) [yes]")),
            "jointData item 13 (torque): expected the flag [ok] or [fail], got [yes]");
  EXPECT_EQ(error_of(two_axes_with(9, "(0 1.5) [ok]")),
            "jointData item 18 (controlMode): value 1 is not an integer or a vocab: 1.5");
  EXPECT_EQ(error_of(two_axes_with(2, "(1.0 2.0 3.0) [ok]")),
            "jointData item 4 (jointAcceleration): has 3 values, but jointPosition has 2");
  // A field flagged [fail] is read with its flag, not refused.
  const JointData d = decode_joint_data(Bottle::from_text(two_axes_with(1, "(0.0 0.0) [fail]")));
  EXPECT_FALSE(d.velocity.valid);
  EXPECT_TRUE(d.position.valid);
  EXPECT_EQ(d.position.values, (std::vector<double>{1.5, 2.5}));
}
