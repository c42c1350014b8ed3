// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The running application's part of the bootloader class (core/rg_board_boot.c): it says who it
// is, and restarts into the bootloader only when asked with the key, at its own address, with its
// motors stopped first.
#include <gtest/gtest.h>

#include "fake_board.hpp"
#include "rg_boot.h"

namespace {

constexpr unsigned kBoot = ROBOGENE_CAN_CLASS_BOOTLOADER;

TEST(CoreBoardBootloaderClass, IdentifyNamesTheApplicationItsBoardAndRevision) {
  rg_test::FakeBoard b;
  b.params.board_id = 3;
  b.start();
  for (unsigned dst : {1u, unsigned{ROBOGENE_CAN_BROADCAST_ADDRESS}}) {
    const auto r = b.command({ROBOGENE_CAN_CMD_BOOTLOADER_IDENTIFY}, 0, dst, kBoot);
    ASSERT_TRUE(r) << dst;
    EXPECT_EQ(r->id, ROBOGENE_CAN_ID(kBoot, 1, 0));
    ASSERT_EQ(r->len, ROBOGENE_CAN_LEN_BOOTLOADER_IDENTIFY_REPLY);
    EXPECT_EQ(r->data[1], ROBOGENE_CAN_BOARD_TYPE_ROBOGENE_MOTOR_BOARD);
    EXPECT_EQ(r->data[2], 3) << "the board it was built for, not its CAN address";
    EXPECT_EQ(r->data[3], ROBOGENE_BOARD_REVISION);
    EXPECT_EQ(r->data[4], ROBOGENE_CAN_FIRMWARE_STAGE_APPLICATION);
    EXPECT_EQ(r->data[6], RG_FIRMWARE_VERSION);
  }
}

TEST(CoreBoardBootloaderClass, EnterBootloaderNeedsTheKeyAndThisBoardsAddressAndStopsTheMotors) {
  rg_test::FakeBoard b;
  b.start();
  ASSERT_FALSE(b.command({ROBOGENE_CAN_CMD_SET_CONTROL_MODE, ROBOGENE_CAN_CONTROL_MODE_POSITION}));
  ASSERT_FALSE(b.command(rg_test::position_move(5000, 1000)));
  b.run(0.05);
  ASSERT_TRUE(b.plant[0].enabled);
  EXPECT_FALSE(b.command(rg_test::le32(ROBOGENE_CAN_CMD_ENTER_BOOTLOADER, 0x12345678), 0, 1, kBoot));
  EXPECT_FALSE(b.command(rg_test::le32(ROBOGENE_CAN_CMD_ENTER_BOOTLOADER, RG_BOOT_ENTER_KEY), 0,
                         ROBOGENE_CAN_BROADCAST_ADDRESS, kBoot));
  EXPECT_EQ(b.bootloader_requests, 0) << "a wrong key or a broadcast restarts nothing";
  EXPECT_TRUE(b.plant[0].enabled);
  EXPECT_FALSE(b.command(rg_test::le32(ROBOGENE_CAN_CMD_ENTER_BOOTLOADER, RG_BOOT_ENTER_KEY), 0, 1, kBoot));
  EXPECT_EQ(b.bootloader_requests, 1);
  EXPECT_FALSE(b.plant[0].enabled);
  EXPECT_FALSE(b.plant[1].enabled);
  EXPECT_EQ(b.mode(0), ROBOGENE_CAN_CONTROL_MODE_IDLE);
}

TEST(CoreBoardBootloaderClass, TheBootloadersUpdateCommandsDoNothingInTheApplication) {
  rg_test::FakeBoard b;
  b.start();
  EXPECT_FALSE(b.command(rg_test::le32(ROBOGENE_CAN_CMD_BOOTLOADER_ERASE, 4096), 0, 1, kBoot));
  EXPECT_FALSE(b.command({ROBOGENE_CAN_CMD_BOOTLOADER_START}, 0, 1, kBoot));
  EXPECT_EQ(b.core.rejected_frames, 0u);
  EXPECT_FALSE(b.command({0x40}, 0, 1, kBoot));
  EXPECT_EQ(b.core.rejected_frames, 1u);
}

}  // namespace
