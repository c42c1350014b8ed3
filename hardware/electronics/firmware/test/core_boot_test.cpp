// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The bootloader's state machine (core/rg_boot.c) frame by frame on a fake flash: the update a
// host runs, and every way one goes wrong: out-of-order and repeated writes, an image for another
// board or revision, a corrupted transfer, a flash error, an update cut short.
#include <gtest/gtest.h>

#include "fake_flash.hpp"
#include "rg_wire.h"

namespace {

using rg_test::FakeFlash;
using rg_test::stamped_image;

constexpr std::uint8_t kAddress = 3;
const rg_image_target_t kTarget{ROBOGENE_CAN_BOARD_TYPE_ROBOGENE_MOTOR_BOARD, 3, 'C'};

rg_can_frame_t command(std::uint8_t code, std::vector<std::uint8_t> payload, std::uint8_t dst = kAddress) {
  rg_can_frame_t f{};
  f.id = static_cast<std::uint16_t>(ROBOGENE_CAN_ID(ROBOGENE_CAN_CLASS_BOOTLOADER, 0, dst));
  f.len = static_cast<std::uint8_t>(1 + payload.size());
  f.data[0] = code;
  std::memcpy(f.data + 1, payload.data(), payload.size());
  return f;
}

std::vector<std::uint8_t> u32(std::uint32_t v) {
  std::vector<std::uint8_t> p(4);
  rg_put_u32(p.data(), v);
  return p;
}

struct CoreBootloader : ::testing::Test {
  FakeFlash flash;
  rg_boot_t boot{};

  void SetUp() override { rg_boot_init(&boot, kAddress, &kTarget, &flash.hal); }

  // Sends one frame and returns the board's single reply.
  rg_can_frame_t ask(const rg_can_frame_t& f) {
    flash.sent.clear();
    rg_boot_receive(&boot, &f);
    EXPECT_EQ(flash.sent.size(), 1u) << "one reply per command";
    return flash.sent.empty() ? rg_can_frame_t{} : flash.sent.front();
  }
  std::uint8_t erase(std::uint32_t size) {
    return ask(command(ROBOGENE_CAN_CMD_BOOTLOADER_ERASE, u32(size))).data[ROBOGENE_CAN_BOOTLOADER_ERASE_REPLY_STATUS_BYTE];
  }
  // (acknowledged sequence, status)
  std::pair<std::uint16_t, std::uint8_t> write(std::uint16_t seq, const std::vector<std::uint8_t>& img) {
    std::vector<std::uint8_t> p(6, 0xFF);
    rg_put_u16(p.data(), seq);
    for (std::size_t i = 0; i < 4 && 4u * seq + i < img.size(); ++i) p[2 + i] = img[4u * seq + i];
    const rg_can_frame_t r = ask(command(ROBOGENE_CAN_CMD_BOOTLOADER_WRITE, p));
    return {rg_get_u16(r.data + 1), r.data[3]};
  }
  std::uint8_t write_all(const std::vector<std::uint8_t>& img) {
    const std::uint16_t words = static_cast<std::uint16_t>((img.size() + 3) / 4);
    for (std::uint16_t s = 0; s < words; ++s) {
      const auto [ack, status] = write(s, img);
      if (status != ROBOGENE_CAN_BOOT_STATUS_OK) return status;
      EXPECT_EQ(ack, s);
    }
    return ROBOGENE_CAN_BOOT_STATUS_OK;
  }
  std::pair<std::uint8_t, std::uint32_t> verify() {
    const rg_can_frame_t r = ask(command(ROBOGENE_CAN_CMD_BOOTLOADER_VERIFY, {}));
    EXPECT_EQ(r.len, ROBOGENE_CAN_LEN_BOOTLOADER_VERIFY_REPLY);
    return {r.data[1], rg_get_u32(r.data + 2)};
  }
  std::uint8_t start() { return ask(command(ROBOGENE_CAN_CMD_BOOTLOADER_START, {})).data[1]; }
  rg_can_frame_t identify(std::uint8_t dst = kAddress) { return ask(command(ROBOGENE_CAN_CMD_BOOTLOADER_IDENTIFY, {}, dst)); }
};

TEST_F(CoreBootloader, ACompleteUpdateErasesWritesVerifiesAndStartsTheImage) {
  const auto img = stamped_image(5000, 3);  // not a multiple of 8: the last unit is padded
  EXPECT_FALSE(boot.image_valid);
  EXPECT_EQ(erase(static_cast<std::uint32_t>(img.size())), ROBOGENE_CAN_BOOT_STATUS_OK);
  EXPECT_EQ(flash.erases, 3);  // 5000 bytes: three 2 KiB pages
  EXPECT_EQ(write_all(img), ROBOGENE_CAN_BOOT_STATUS_OK);
  EXPECT_EQ(std::vector<std::uint8_t>(flash.cells.begin(), flash.cells.begin() + 5000), img);
  EXPECT_EQ(flash.cells[5000], 0xFF);
  const auto [status, crc] = verify();
  EXPECT_EQ(status, ROBOGENE_CAN_BOOT_STATUS_OK);
  EXPECT_EQ(crc, rg_get_u32(img.data() + RG_IMAGE_HEADER_OFFSET + RG_IMAGE_CRC_AT));
  EXPECT_TRUE(boot.image_valid);
  EXPECT_EQ(flash.starts, 0);
  EXPECT_EQ(start(), ROBOGENE_CAN_BOOT_STATUS_OK);
  EXPECT_EQ(flash.starts, 1);
  // The reply comes from the board to the host, in the bootloader class, before the start.
  EXPECT_EQ(flash.sent.front().id, ROBOGENE_CAN_ID(ROBOGENE_CAN_CLASS_BOOTLOADER, kAddress, 0));
}

TEST_F(CoreBootloader, IdentifyNamesTheBoardTheRevisionAndWhetherAnImageIsThere) {
  rg_can_frame_t r = identify();
  ASSERT_EQ(r.len, ROBOGENE_CAN_LEN_BOOTLOADER_IDENTIFY_REPLY);
  EXPECT_EQ(r.data[0], ROBOGENE_CAN_CMD_BOOTLOADER_IDENTIFY);
  EXPECT_EQ(r.data[1], ROBOGENE_CAN_BOARD_TYPE_ROBOGENE_MOTOR_BOARD);
  EXPECT_EQ(r.data[2], 3);
  EXPECT_EQ(r.data[3], 'C');
  EXPECT_EQ(r.data[4], ROBOGENE_CAN_FIRMWARE_STAGE_BOOTLOADER);
  EXPECT_EQ(r.data[5], 0);
  const auto img = stamped_image(3000, 3);
  std::memcpy(flash.cells.data(), img.data(), img.size());
  rg_boot_init(&boot, kAddress, &kTarget, &flash.hal);  // a reset: the region is checked again
  EXPECT_EQ(identify(ROBOGENE_CAN_BROADCAST_ADDRESS).data[5], 1) << "identify is answered at the broadcast address too";
}

TEST_F(CoreBootloader, OnlyTheHostsBootloaderFramesToThisBoardAreTakenAndMalformedOnesCounted) {
  rg_can_frame_t other = command(ROBOGENE_CAN_CMD_BOOTLOADER_IDENTIFY, {}, 2);
  rg_can_frame_t from_board = command(ROBOGENE_CAN_CMD_BOOTLOADER_IDENTIFY, {});
  from_board.id = static_cast<std::uint16_t>(ROBOGENE_CAN_ID(ROBOGENE_CAN_CLASS_BOOTLOADER, 1, kAddress));
  rg_can_frame_t motor = command(ROBOGENE_CAN_CMD_BOOTLOADER_IDENTIFY, {});
  motor.id = static_cast<std::uint16_t>(ROBOGENE_CAN_ID(ROBOGENE_CAN_CLASS_POLLING_MOTOR_CONTROL, 0, kAddress));
  for (const auto& f : {other, from_board, motor}) rg_boot_receive(&boot, &f);
  EXPECT_TRUE(flash.sent.empty());
  EXPECT_EQ(boot.rejected_frames, 0u);
  rg_can_frame_t short_erase = command(ROBOGENE_CAN_CMD_BOOTLOADER_ERASE, {1, 2});
  rg_can_frame_t unknown = command(0x42, {});
  rg_boot_receive(&boot, &short_erase);
  rg_boot_receive(&boot, &unknown);
  EXPECT_TRUE(flash.sent.empty());
  EXPECT_EQ(boot.rejected_frames, 2u);
  EXPECT_EQ(flash.erases, 0);
  // A broadcast erase is never taken: every board on the bus would wipe its application.
  rg_can_frame_t all = command(ROBOGENE_CAN_CMD_BOOTLOADER_ERASE, u32(4096), ROBOGENE_CAN_BROADCAST_ADDRESS);
  rg_boot_receive(&boot, &all);
  EXPECT_TRUE(flash.sent.empty());
  EXPECT_EQ(flash.erases, 0);
}

TEST_F(CoreBootloader, WritesOutOfOrderAreRefusedNamingTheSequenceExpectedAndRepeatsAreAcknowledged) {
  const auto img = stamped_image(4096, 3);
  EXPECT_EQ(write(0, img).second, ROBOGENE_CAN_BOOT_STATUS_BAD_STATE) << "no write before an erase";
  ASSERT_EQ(erase(4096), ROBOGENE_CAN_BOOT_STATUS_OK);
  EXPECT_EQ(write(0, img), std::make_pair(std::uint16_t{0}, std::uint8_t{ROBOGENE_CAN_BOOT_STATUS_OK}));
  EXPECT_EQ(write(1, img).second, ROBOGENE_CAN_BOOT_STATUS_OK);
  // A lost acknowledgement: the host sends 1 again; it is acknowledged and not programmed twice.
  EXPECT_EQ(write(1, img), std::make_pair(std::uint16_t{1}, std::uint8_t{ROBOGENE_CAN_BOOT_STATUS_OK}));
  // A lost frame: 3 arrives where 2 was expected.
  EXPECT_EQ(write(3, img), std::make_pair(std::uint16_t{2}, std::uint8_t{ROBOGENE_CAN_BOOT_STATUS_BAD_SEQUENCE}));
  for (std::uint16_t s = 2; s < 1024; ++s) ASSERT_EQ(write(s, img).second, ROBOGENE_CAN_BOOT_STATUS_OK) << s;
  EXPECT_EQ(write(1024, img).second, ROBOGENE_CAN_BOOT_STATUS_BAD_STATE) << "past the size erased";
  EXPECT_EQ(verify().first, ROBOGENE_CAN_BOOT_STATUS_OK);
}

TEST_F(CoreBootloader, EraseRefusesSizesOutsideTheRegionAndReportsFlashErrors) {
  EXPECT_EQ(erase(FakeFlash::kRegion + 1), ROBOGENE_CAN_BOOT_STATUS_OUT_OF_RANGE);
  EXPECT_EQ(erase(16), ROBOGENE_CAN_BOOT_STATUS_BAD_HEADER);
  EXPECT_EQ(flash.erases, 0);
  flash.fail_erase_page = 1;
  EXPECT_EQ(erase(4096), ROBOGENE_CAN_BOOT_STATUS_FLASH_ERROR);
  EXPECT_EQ(write(0, stamped_image(4096, 3)).second, ROBOGENE_CAN_BOOT_STATUS_BAD_STATE);
  flash.fail_erase_page.reset();
  flash.fail_program_at = 8;
  ASSERT_EQ(erase(4096), ROBOGENE_CAN_BOOT_STATUS_OK);
  const auto img = stamped_image(4096, 3);
  EXPECT_EQ(write_all(img), ROBOGENE_CAN_BOOT_STATUS_FLASH_ERROR);
  EXPECT_EQ(verify().first, ROBOGENE_CAN_BOOT_STATUS_BAD_STATE);
}

TEST_F(CoreBootloader, AnImageForAnotherBoardIsRefusedOnceItsHeaderIsWritten) {
  const auto img = stamped_image(4096, 1);  // built for the neck board
  ASSERT_EQ(erase(4096), ROBOGENE_CAN_BOOT_STATUS_OK);
  const std::uint16_t header_end_word = RG_IMAGE_HEADER_END / 4 - 1;
  for (std::uint16_t s = 0; s < header_end_word; ++s) ASSERT_EQ(write(s, img).second, ROBOGENE_CAN_BOOT_STATUS_OK);
  EXPECT_EQ(write(header_end_word, img).second, ROBOGENE_CAN_BOOT_STATUS_WRONG_BOARD);
  EXPECT_EQ(write(header_end_word + 1, img).second, ROBOGENE_CAN_BOOT_STATUS_BAD_STATE);
  EXPECT_EQ(verify().first, ROBOGENE_CAN_BOOT_STATUS_BAD_STATE);
  EXPECT_EQ(start(), ROBOGENE_CAN_BOOT_STATUS_NO_IMAGE);
  EXPECT_EQ(flash.starts, 0);
}

TEST_F(CoreBootloader, AnImageForAnotherRevisionOrBoardTypeIsRefused) {
  ASSERT_EQ(erase(4096), ROBOGENE_CAN_BOOT_STATUS_OK);
  EXPECT_EQ(write_all(stamped_image(4096, 3, 'B')), ROBOGENE_CAN_BOOT_STATUS_WRONG_REVISION);
  ASSERT_EQ(erase(4096), ROBOGENE_CAN_BOOT_STATUS_OK);
  EXPECT_EQ(write_all(stamped_image(4096, 3, 'C', ROBOGENE_CAN_BOARD_TYPE_MC4_4DC)), ROBOGENE_CAN_BOOT_STATUS_WRONG_BOARD);
  ASSERT_EQ(erase(4096), ROBOGENE_CAN_BOOT_STATUS_OK);
  EXPECT_EQ(write_all(stamped_image(4000, 3)), ROBOGENE_CAN_BOOT_STATUS_BAD_HEADER) << "a header whose size is not the size erased";
  ASSERT_EQ(erase(4096), ROBOGENE_CAN_BOOT_STATUS_OK);
  auto no_magic = stamped_image(4096, 3);
  no_magic[RG_IMAGE_HEADER_OFFSET] ^= 0xFF;
  EXPECT_EQ(write_all(no_magic), ROBOGENE_CAN_BOOT_STATUS_BAD_HEADER);
}

TEST_F(CoreBootloader, ACorruptedTransferFailsVerifyAndIsNeverStarted) {
  auto img = stamped_image(6000, 3);
  img[4000] ^= 0x10;  // one bit flipped after stamping: what a bad link or a bad file would do
  ASSERT_EQ(erase(6000), ROBOGENE_CAN_BOOT_STATUS_OK);
  ASSERT_EQ(write_all(img), ROBOGENE_CAN_BOOT_STATUS_OK);
  const auto [status, crc] = verify();
  EXPECT_EQ(status, ROBOGENE_CAN_BOOT_STATUS_CRC_MISMATCH);
  EXPECT_NE(crc, rg_get_u32(img.data() + RG_IMAGE_HEADER_OFFSET + RG_IMAGE_CRC_AT));
  EXPECT_FALSE(boot.image_valid);
  EXPECT_EQ(start(), ROBOGENE_CAN_BOOT_STATUS_NO_IMAGE);
  EXPECT_EQ(flash.starts, 0);
}

TEST_F(CoreBootloader, AnUpdateCutShortLeavesNoImageToStartAndASecondUpdateSucceeds) {
  const auto good = stamped_image(8000, 3);
  ASSERT_EQ(erase(8000), ROBOGENE_CAN_BOOT_STATUS_OK);
  ASSERT_EQ(write_all(good), ROBOGENE_CAN_BOOT_STATUS_OK);
  ASSERT_EQ(verify().first, ROBOGENE_CAN_BOOT_STATUS_OK);
  // A newer image, interrupted after half of it: the host went away, then the board was reset.
  auto newer = stamped_image(8000, 3);
  newer[7000] = 0x55;
  rg_test::put32(newer, RG_IMAGE_HEADER_OFFSET + RG_IMAGE_CRC_AT, 0);
  rg_test::put32(newer, RG_IMAGE_HEADER_OFFSET + RG_IMAGE_CRC_AT, rg_crc32(0, newer.data(), newer.size()));
  ASSERT_EQ(erase(8000), ROBOGENE_CAN_BOOT_STATUS_OK);
  for (std::uint16_t s = 0; s < 1000; ++s) ASSERT_EQ(write(s, newer).second, ROBOGENE_CAN_BOOT_STATUS_OK);
  EXPECT_FALSE(rg_boot_image_valid(&flash.hal, &kTarget)) << "the reset check must not start half an image";
  rg_boot_init(&boot, kAddress, &kTarget, &flash.hal);
  EXPECT_EQ(identify().data[5], 0);
  EXPECT_EQ(start(), ROBOGENE_CAN_BOOT_STATUS_NO_IMAGE);
  EXPECT_EQ(verify().first, ROBOGENE_CAN_BOOT_STATUS_BAD_STATE);
  ASSERT_EQ(erase(8000), ROBOGENE_CAN_BOOT_STATUS_OK);
  ASSERT_EQ(write_all(newer), ROBOGENE_CAN_BOOT_STATUS_OK);
  EXPECT_EQ(verify().first, ROBOGENE_CAN_BOOT_STATUS_OK);
  EXPECT_EQ(start(), ROBOGENE_CAN_BOOT_STATUS_OK);
  EXPECT_EQ(flash.starts, 1);
}

TEST(CoreImage, TheCrcIsZlibsAndSkipsTheCrcField) {
  const std::uint8_t check[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(rg_crc32(0, check, sizeof check), 0xCBF43926u);  // the CRC-32 check value
  EXPECT_EQ(rg_crc32(rg_crc32(0, check, 4), check + 4, 5), 0xCBF43926u);
  const auto img = stamped_image(2048, 3);
  auto other_crc = img;
  rg_test::put32(other_crc, RG_IMAGE_HEADER_OFFSET + RG_IMAGE_CRC_AT, 0x12345678u);
  bool ok = false;
  auto read = [](void* ctx, std::uint32_t off, std::uint8_t* out, std::uint32_t len) {
    const auto& v = *static_cast<std::vector<std::uint8_t>*>(ctx);
    std::memcpy(out, v.data() + off, len);
    return true;
  };
  const std::uint32_t a = rg_image_crc(read, const_cast<std::vector<std::uint8_t>*>(&img), 2048, &ok);
  EXPECT_TRUE(ok);
  EXPECT_EQ(a, rg_image_crc(read, &other_crc, 2048, &ok));
  EXPECT_EQ(rg_image_check(read, const_cast<std::vector<std::uint8_t>*>(&img), 4096, &kTarget, nullptr), ROBOGENE_CAN_BOOT_STATUS_OK);
  EXPECT_EQ(rg_image_check(read, &other_crc, 4096, &kTarget, nullptr), ROBOGENE_CAN_BOOT_STATUS_CRC_MISMATCH);
}

}  // namespace
