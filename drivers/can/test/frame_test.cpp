// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include "robogene/can/bus.hpp"
#include "robogene/can/frame.hpp"

namespace robogene::can {
namespace {

TEST(CanFrame, CompactFormIsCandumps) {
  EXPECT_EQ(to_string(Frame(0x123, {0xDE, 0xAD, 0xBE, 0xEF})), "123#DEADBEEF");
  EXPECT_EQ(to_string(Frame(0x00B, {})), "00B#");
}

TEST(CanFrame, ElevenBitIdAndEightBytesAreTheLimits) {
  EXPECT_NO_THROW(Frame(0x7FF, {1, 2, 3, 4, 5, 6, 7, 8}));
  try {
    Frame(0x800, {});
    FAIL() << "0x800 accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("0x800"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("11 bits"), std::string::npos) << e.what();
  }
  EXPECT_THROW(Frame(0x100, std::vector<std::uint8_t>(9, 0)), Error);
  Frame f;
  f.id = 0x100;
  f.len = 9;
  EXPECT_THROW(validate(f), Error);
}

TEST(CanFrame, EqualityIgnoresBytesPastTheLength) {
  Frame a(0x10, {1, 2});
  Frame b = a;
  b.data[5] = 99;
  EXPECT_EQ(a, b);
  b.data[1] = 3;
  EXPECT_NE(a, b);
}

TEST(CanFilter, MatchesAsCanRawFilterDoes) {
  const Filter class1{0x100, 0x700};
  EXPECT_TRUE(class1.matches(0x131));
  EXPECT_FALSE(class1.matches(0x031));
  EXPECT_TRUE(passes({}, 0x7FF));
  EXPECT_TRUE(passes({{0x010, 0x7FF}, class1}, 0x010));
  EXPECT_FALSE(passes({{0x010, 0x7FF}, class1}, 0x011));
}

TEST(CanBusSpec, UnknownBackendOrEmptyNameIsNamed) {
  for (const char* spec : {"vcan0", "serial:ttyS0", "socketcan:", "virtual:"}) {
    try {
      open_bus(spec);
      FAIL() << spec << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(spec), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("socketcan:IFACE"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace robogene::can
