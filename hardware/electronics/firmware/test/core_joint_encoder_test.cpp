// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The AS5048A's read frames as they come off the wire (bit 15 even parity over the frame, bit 14 the
// error flag, bits 13..0 the angle), and when an axis's stream of frames is trusted.
#include <gtest/gtest.h>

#include "rg_joint_encoder.h"

namespace {

TEST(CoreJointEncoder, DecodesGoodFrames) {
  std::uint16_t angle = 0;
  // 0x1234 has five ones: the sensor sets the parity bit to make them even.
  EXPECT_EQ(rg_as5048a_decode(0x9234, &angle), RG_AS5048A_FRAME_OK);
  EXPECT_EQ(angle, 0x1234);
  EXPECT_EQ(rg_as5048a_decode(0x3FFF, &angle), RG_AS5048A_FRAME_OK);  // fourteen ones: no parity bit
  EXPECT_EQ(angle, 0x3FFF);
  EXPECT_EQ(rg_as5048a_decode(0x8001, &angle), RG_AS5048A_FRAME_OK);
  EXPECT_EQ(angle, 1);
}

TEST(CoreJointEncoder, RefusesBadParity) {
  std::uint16_t angle = 77;
  EXPECT_EQ(rg_as5048a_decode(0x1234, &angle), RG_AS5048A_FRAME_BAD_PARITY);  // the parity bit lost
  EXPECT_EQ(rg_as5048a_decode(0x9235, &angle), RG_AS5048A_FRAME_BAD_PARITY);  // one data bit flipped
  EXPECT_EQ(rg_as5048a_decode(0x8000, &angle), RG_AS5048A_FRAME_BAD_PARITY);
  EXPECT_EQ(angle, 77) << "a bad frame gives no angle";
}

TEST(CoreJointEncoder, RefusesTheErrorFlag) {
  std::uint16_t angle = 77;
  EXPECT_EQ(rg_as5048a_decode(0x4001, &angle), RG_AS5048A_FRAME_ERROR_FLAG);  // parity good, flag set
  // All ones (a data line stuck high): sixteen ones is even parity, but the error flag is set.
  EXPECT_EQ(rg_as5048a_decode(0xFFFF, &angle), RG_AS5048A_FRAME_ERROR_FLAG);
  EXPECT_EQ(angle, 77);
}

TEST(CoreJointEncoder, AllZerosDecodesAsAngleZero) {
  // The missing encoder's line, pulled down: a frame that checks. Only the stream tells it apart.
  std::uint16_t angle = 77;
  EXPECT_EQ(rg_as5048a_decode(0x0000, &angle), RG_AS5048A_FRAME_OK);
  EXPECT_EQ(angle, 0);
}

TEST(CoreJointEncoder, BuildsFramesThatDecode) {
  EXPECT_EQ(rg_as5048a_frame(0x1234, false), 0x9234);
  EXPECT_EQ(rg_as5048a_frame(0x3FFF, false), 0x3FFF);
  EXPECT_EQ(rg_as5048a_frame(0x0001, true), 0x4001);
  for (std::uint16_t a = 0; a < 0x4000; a = static_cast<std::uint16_t>(a + 97)) {
    std::uint16_t back = 0xFFFF;
    ASSERT_EQ(rg_as5048a_decode(rg_as5048a_frame(a, false), &back), RG_AS5048A_FRAME_OK) << a;
    ASSERT_EQ(back, a);
  }
}

std::uint8_t feed(rg_joint_encoder_t& e, std::uint16_t frame, unsigned times) {
  std::uint8_t s = e.state;
  for (unsigned i = 0; i < times; ++i) s = rg_joint_encoder_update(&e, frame);
  return s;
}

TEST(CoreJointEncoder, TrustsAnAngleAfterEnoughGoodFrames) {
  rg_joint_encoder_t e;
  rg_joint_encoder_start(&e);
  EXPECT_EQ(feed(e, 0x9234, RG_JOINT_ENCODER_GOOD_FRAMES - 1), RG_JOINT_ENCODER_STARTING);
  EXPECT_EQ(feed(e, 0x9234, 1), RG_JOINT_ENCODER_OK);
  EXPECT_EQ(e.angle, 0x1234);
}

TEST(CoreJointEncoder, ForgivesOneBadFrameButFailsOnARun) {
  rg_joint_encoder_t e;
  rg_joint_encoder_start(&e);
  feed(e, 0x9234, RG_JOINT_ENCODER_GOOD_FRAMES);
  EXPECT_EQ(feed(e, 0x1234, 1), RG_JOINT_ENCODER_OK) << "one glitch on the cable";
  EXPECT_EQ(e.angle, 0x1234) << "the last good angle stays";
  feed(e, 0x9234, 1);
  EXPECT_EQ(feed(e, 0x1234, RG_JOINT_ENCODER_BAD_FRAMES), RG_JOINT_ENCODER_FAILED);
  EXPECT_EQ(e.bad_frames, 1 + RG_JOINT_ENCODER_BAD_FRAMES);
  // Good frames again: trusted only after a whole run of them.
  EXPECT_EQ(feed(e, 0x9234, 1), RG_JOINT_ENCODER_STARTING);
  EXPECT_EQ(feed(e, 0x9234, RG_JOINT_ENCODER_GOOD_FRAMES), RG_JOINT_ENCODER_OK);
}

TEST(CoreJointEncoder, ASensorReportingItsErrorFlagFails) {
  rg_joint_encoder_t e;
  rg_joint_encoder_start(&e);
  EXPECT_EQ(feed(e, 0xFFFF, RG_JOINT_ENCODER_BAD_FRAMES), RG_JOINT_ENCODER_FAILED);
}

TEST(CoreJointEncoder, AllZerosIsAMissingEncoderNeverATrustedZero) {
  rg_joint_encoder_t e;
  rg_joint_encoder_start(&e);
  EXPECT_EQ(feed(e, 0x0000, RG_JOINT_ENCODER_ZERO_FRAMES - 1), RG_JOINT_ENCODER_STARTING);
  EXPECT_EQ(feed(e, 0x0000, 1), RG_JOINT_ENCODER_ABSENT);
  EXPECT_EQ(feed(e, 0x0000, 100), RG_JOINT_ENCODER_ABSENT);
}

TEST(CoreJointEncoder, ALiveSensorPassingThroughZeroStaysTrusted) {
  rg_joint_encoder_t e;
  rg_joint_encoder_start(&e);
  feed(e, 0x8001, RG_JOINT_ENCODER_GOOD_FRAMES);
  EXPECT_EQ(feed(e, 0x0000, 5), RG_JOINT_ENCODER_OK);
  EXPECT_EQ(feed(e, 0x3FFF, 1), RG_JOINT_ENCODER_OK);
}

}  // namespace
