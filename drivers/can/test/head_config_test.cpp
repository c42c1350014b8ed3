// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <fstream>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "head_config_fixture.hpp"

namespace robogene::can {
namespace {

std::string head_ini_text() {
  std::ifstream in(testing::head_ini_path());
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The generated head.ini with one line replaced; the error must name file:line, group and key.
std::string error_for(const std::string& line_start, const std::string& replacement) {
  std::string text = head_ini_text();
  const auto at = text.find("\n" + line_start);
  EXPECT_NE(at, std::string::npos) << line_start;
  const auto end = text.find('\n', at + 1);
  text.replace(at + 1, end - at - 1, replacement);
  try {
    read_head_config(dev::Property::from_ini(text, "head.ini"));
  } catch (const dev::ConfigError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(HeadConfig, TheGeneratedHeadIniDescribesSixJointsOnThreeBoards) {
  const HeadConfig head = testing::head_config();
  ASSERT_EQ(head.joints.size(), 6U);
  ASSERT_EQ(head.boards.size(), 3U);
  EXPECT_EQ(head.joints[4].name, "eyes_version");
  const BoardConfig* eyes = head.board(head.joints[4].board);
  ASSERT_NE(eyes, nullptr);
  ASSERT_TRUE(eyes->coupling);
  EXPECT_EQ(eyes->coupling->joints[0], 4);
  EXPECT_EQ(eyes->joints[1], 5);
  EXPECT_FALSE(head.board(head.joints[0].board)->coupling);
  // The eyes press their stops with the homing run's own current, below the run limit.
  EXPECT_EQ(head.joints[4].homing.current, 100);
  EXPECT_LT(head.joints[4].homing.current, head.joints[4].current_limit);
  EXPECT_EQ(head.joints[0].homing.current, 0);
}

TEST(HeadConfig, BrakesAreReadPerJointAndOptional) {
  const HeadConfig head = testing::head_config();
  std::vector<bool> braked;
  for (const auto& j : head.joints) braked.push_back(j.has_brake);
  EXPECT_EQ(braked, (std::vector<bool>{true, true, false, false, false, false})) << "pitch and roll carry brakes";
  std::string text = head_ini_text();
  const auto at = text.find("\nbrake ");
  ASSERT_NE(at, std::string::npos);
  text.erase(at + 1, text.find('\n', at + 1) - at);
  const HeadConfig without = read_head_config(dev::Property::from_ini(text, "head.ini"));
  for (const auto& j : without.joints) EXPECT_FALSE(j.has_brake) << j.name << ": a config without brake has none";
}

TEST(HeadConfig, BadFieldsAreNamedWithFileLineGroupAndKey) {
  struct Case {
    const char* line;
    const char* replacement;
    const char* expected;
  };
  for (const Case& c : {
           Case{"axis ", "axis 0 1 0 1 0", "[GENERAL] key 'axis': expected 6 values"},
           Case{"axis ", "axis 0 0 0 1 0 1", "neck_pitch and neck_roll are both on board 1 axis 0"},
           Case{"board ", "board 1 1 2 2 3 9", "on board 9, which [CAN] board_addresses does not list"},
           Case{"encoder ", "encoder 1 1 1 1 1 \"x\"", "[GENERAL] key 'encoder': value 6 (x) is not a number"},
           Case{"max ", "max 22 20 45 30 30 -5", "joint eyes_vergence: max -5 is not above min 0"},
           Case{"protocol_fingerprint", "protocol_fingerprint \"0000\"", "[CAN] key 'protocol_fingerprint'"},
           Case{"m2j", "m2j (0.5 0.5) (1 1)", "[COUPLING_3] key 'm2j': is not the inverse of j2m"},
           Case{"board_addresses", "board_addresses 1 2 2", "address 2 is used by two boards"},
           Case{"kp ", "kp 170 170 66 35 130 99999", "[PIDS] key 'kp': value 6 (99999) is outside"},
           Case{"current 0 ", "current 0 0 0 0 0 0",
                "[HOMING] key 'current': joint eyes_version homes with 0 mA, outside 1..its current limit (600 mA"},
           Case{"current 0 ", "current 0 0 0 0 601 0",
                "[HOMING] key 'current': joint eyes_version homes with 601 mA, outside 1..its current limit (600 mA"},
           Case{"current 0 ", "current 0 0 0 0 100", "[HOMING] key 'current': expected 6 values"},
           Case{"brake ", "brake 1 2 0 0 0 0", "[GENERAL] key 'brake': value 2 (2) is outside [0, 1]"},
           Case{"brake ", "brake 1 1 0 0 1 0",
                "[GENERAL] key 'brake': joint eyes_version has a brake, but board 3 couples its motors"},
       }) {
    const std::string what = error_for(c.line, c.replacement);
    EXPECT_NE(what.find(c.expected), std::string::npos) << c.replacement << " -> " << what;
    EXPECT_EQ(what.rfind("head.ini:", 0), 0U) << what;
  }
  std::string text = head_ini_text();
  text.replace(text.find("[LIMITS]"), 8, "[LIMITZ]");
  try {
    read_head_config(dev::Property::from_ini(text, "head.ini"));
    FAIL();
  } catch (const dev::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("missing group [LIMITS]"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace robogene::can

namespace robogene::can {
namespace {

TEST(HeadConfig, JointEncodersAreReadPerJointAndBadOnesNamed) {
  const HeadConfig head = testing::head_config();
  std::vector<int> bits;
  for (const auto& j : head.joints) bits.push_back(j.joint_encoder_bits);
  EXPECT_EQ(bits, (std::vector<int>{14, 14, 14, 14, 0, 0})) << "the neck and the eye tilt have AS5048As";
  EXPECT_NE(error_for("joint_encoder_bits ", "joint_encoder_bits 14 12 14 14 0 0")
                .find("[GENERAL] key 'joint_encoder_bits': joint neck_roll: 12 bits; the boards read AS5048A joint encoders (14 bits) or none (0)"),
            std::string::npos);
  EXPECT_NE(error_for("joint_encoder_bits ", "joint_encoder_bits 14 14 14 14 14 0")
                .find("joints eyes_version and eyes_vergence on coupled board 3 differ: its firmware derives both from both pans' encoders"),
            std::string::npos);
  EXPECT_NE(error_for("joint_encoder_bits ", "joint_encoder_bits 14 14 14 14 0").find("expected 6 values"), std::string::npos);
}

}  // namespace
}  // namespace robogene::can
