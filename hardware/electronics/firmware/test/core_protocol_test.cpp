// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The control core's CAN side, byte by byte: which frames it takes, what it answers, which
// broadcasts it sends when.
#include <gtest/gtest.h>

#include "fake_board.hpp"
#include "rg_encoder.h"

namespace rg_test {
namespace {

TEST(CoreProtocol, AnswersFirmwareVersionWithTheReplyLayoutOfTheProtocol) {
  FakeBoard b;
  b.start();
  auto r = b.command({ROBOGENE_CAN_CMD_GET_FIRMWARE_VERSION, 1, 0});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->id, 0x010);  // class 0, source 1, destination the host
  ASSERT_EQ(r->len, 8);
  const std::uint8_t want[8] = {91, 200, RG_FIRMWARE_VERSION, RG_FIRMWARE_REVISION, RG_FIRMWARE_BUILD, 1, 0, 1};
  EXPECT_EQ(0, std::memcmp(r->data, want, 8));
  auto newer = b.command({ROBOGENE_CAN_CMD_GET_FIRMWARE_VERSION, 2, 0});
  EXPECT_EQ(newer->data[7], 0) << "a host speaking protocol 2 is not compatible";
}

TEST(CoreProtocol, IgnoresFramesOfOtherClassesSourcesAndBoardsAndCountsMalformedOnes) {
  FakeBoard b;
  b.start();
  rg_can_frame_t f{};
  f.id = static_cast<std::uint16_t>(ROBOGENE_CAN_ID(0, 2, 1));  // from board 2, not the host
  f.len = 1;
  f.data[0] = ROBOGENE_CAN_CMD_GET_BOARD_ID;
  rg_board_receive(&b.core, &f);
  f.id = static_cast<std::uint16_t>(ROBOGENE_CAN_ID(1, 0, 1));  // a broadcast class
  rg_board_receive(&b.core, &f);
  EXPECT_TRUE(b.sent.empty());
  EXPECT_FALSE(b.command({ROBOGENE_CAN_CMD_GET_BOARD_ID}, 0, 2)) << "addressed to board 2";
  auto all = b.command({ROBOGENE_CAN_CMD_GET_BOARD_ID}, 0, ROBOGENE_CAN_BROADCAST_ADDRESS);
  ASSERT_TRUE(all) << "the broadcast address reaches every board";
  EXPECT_EQ(all->data[1], 1);
  EXPECT_EQ(b.core.rejected_frames, 0u);
  EXPECT_FALSE(b.command({ROBOGENE_CAN_CMD_POSITION_MOVE, 1, 2}));  // 3 bytes of a 7-byte command
  EXPECT_FALSE(b.command({120}));                                    // no such command
  EXPECT_EQ(b.core.rejected_frames, 2u);
}

TEST(CoreProtocol, SetBoardIdTakesOnlyBoardAddressesAndKeepsThem) {
  FakeBoard b;
  b.start();
  b.command({ROBOGENE_CAN_CMD_SET_BOARD_ID, 15});
  b.command({ROBOGENE_CAN_CMD_SET_BOARD_ID, 0});
  EXPECT_EQ(b.core.address, 1);
  b.command({ROBOGENE_CAN_CMD_SET_BOARD_ID, 7});
  EXPECT_EQ(b.core.address, 7);
  EXPECT_EQ(b.saved_addresses, std::vector<int>{7});
  auto r = b.command({ROBOGENE_CAN_CMD_GET_BOARD_ID}, 0, 7);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->id, 0x070);
}

TEST(CoreProtocol, RepliesCarryTheAxisBitAndTheAxissOwnValues) {
  FakeBoard b;
  b.params.axes[1].pid.kp = -1234;
  b.start();
  auto r = b.command({ROBOGENE_CAN_CMD_GET_POSITION_PID}, 1);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->data[0], ROBOGENE_CAN_CMD_GET_POSITION_PID | ROBOGENE_CAN_AXIS_BIT);
  EXPECT_EQ(static_cast<std::int16_t>(r->data[1] | (r->data[2] << 8)), -1234);
  b.command(le32(ROBOGENE_CAN_CMD_SET_MAX_POSITION, 123456), 0);
  auto max0 = b.command({ROBOGENE_CAN_CMD_GET_MAX_POSITION}, 0);
  auto max1 = b.command({ROBOGENE_CAN_CMD_GET_MAX_POSITION}, 1);
  EXPECT_EQ(std::vector<std::uint8_t>(max0->data, max0->data + 5), (std::vector<std::uint8_t>{67, 0x40, 0xE2, 0x01, 0x00}));
  EXPECT_EQ(std::vector<std::uint8_t>(max1->data, max1->data + 5), (std::vector<std::uint8_t>{67 | 0x80, 0x20, 0x4E, 0, 0}));
}

TEST(CoreProtocol, BroadcastsRunAtTheirPeriodsAndStatusAlsoOnChange) {
  FakeBoard b;
  b.start();
  b.command(le32(ROBOGENE_CAN_CMD_SET_BROADCAST_POLICY, ROBOGENE_CAN_BROADCAST_MASK_POSITION | ROBOGENE_CAN_BROADCAST_MASK_STATUS));
  b.sent.clear();
  int positions = 0, statuses = 0;
  for (int t = 0; t < 1000; ++t) {
    if (t == 500) b.command({ROBOGENE_CAN_CMD_SET_CONTROL_MODE, ROBOGENE_CAN_CONTROL_MODE_POSITION}, 1);
    b.sent.clear();
    rg_board_tick(&b.core);
    for (const auto& f : b.sent) {
      if (f.id == ROBOGENE_CAN_ID(1, 1, ROBOGENE_CAN_BCAST_POSITION)) ++positions;
      if (f.id == ROBOGENE_CAN_ID(1, 1, ROBOGENE_CAN_BCAST_STATUS)) {
        ++statuses;
        if (t > 500) {
          EXPECT_EQ(f.data[ROBOGENE_CAN_STATUS_BROADCAST_MODE1_BYTE], ROBOGENE_CAN_CONTROL_MODE_POSITION);
        }
      }
    }
  }
  EXPECT_EQ(positions, 200);
  EXPECT_EQ(statuses, 2) << "one at start, one when axis 1 changed mode";
}

TEST(CoreProtocol, StatusCarriesTheControllersErrorsWithoutBeingSentForEachCount) {
  FakeBoard b;
  static std::uint8_t tec = 0;
  b.hal.can_errors = [](void*, std::uint8_t* tx, std::uint8_t* rx, std::uint8_t* status) {
    *tx = tec;
    *rx = 7;
    *status = tec >= 96 ? ROBOGENE_CAN_CAN_STATUS_RX_WARNING : 0;
  };
  b.start();
  b.command(le32(ROBOGENE_CAN_CMD_SET_BROADCAST_POLICY, ROBOGENE_CAN_BROADCAST_MASK_STATUS));
  std::vector<rg_can_frame_t> statuses;
  for (int t = 0; t < 100; ++t) {
    tec = static_cast<std::uint8_t>(t);
    b.sent.clear();
    rg_board_tick(&b.core);
    for (const auto& f : b.sent) statuses.push_back(f);
  }
  ASSERT_EQ(statuses.size(), 2u) << "at start, and when the controller reached error warning";
  EXPECT_EQ(statuses[0].data[ROBOGENE_CAN_STATUS_BROADCAST_TX_ERRORS_BYTE], 0);
  EXPECT_EQ(statuses[0].data[ROBOGENE_CAN_STATUS_BROADCAST_RX_ERRORS_BYTE], 7);
  EXPECT_EQ(statuses[1].data[ROBOGENE_CAN_STATUS_BROADCAST_TX_ERRORS_BYTE], 96);
  EXPECT_EQ(statuses[1].data[ROBOGENE_CAN_STATUS_BROADCAST_CAN_STATUS_BYTE], ROBOGENE_CAN_CAN_STATUS_RX_WARNING);
}

TEST(CoreEncoder, ExtendsTheSixteenBitCounterAcrossWrapsBothWays) {
  rg_encoder_t e;
  rg_encoder_start(&e, 65000);
  EXPECT_EQ(rg_encoder_update(&e, 100), 636);  // forwards through 65535 -> 0
  EXPECT_EQ(rg_encoder_update(&e, 65436), 636 - 200);  // backwards through 0 -> 65535
  std::int32_t counts = 0;
  std::uint16_t raw = 65000;
  rg_encoder_start(&e, raw);
  for (int i = 0; i < 1000; ++i) counts = rg_encoder_update(&e, raw = static_cast<std::uint16_t>(raw + 30000));
  EXPECT_EQ(counts, 30000000) << "a thousand wraps, fast but under half a turn of the counter per tick";
}

}  // namespace
}  // namespace rg_test
