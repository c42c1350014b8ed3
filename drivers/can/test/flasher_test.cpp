// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Updating a board over the bus (robogene::can::flash_firmware, behind `robogene can-flash`)
// against the simulated head on the virtual bus, whose boards run the firmware's bootloader state
// machine on a simulated flash kept in files: complete updates, and every guard: another board's
// image, another revision's, a corrupted one, an update cut short, lost frames, silence.
#include <gtest/gtest.h>

#include "flash_fixture.hpp"
#include "head_config_fixture.hpp"
#include "robogene/can/flasher.hpp"
#include "robogene/can/sim/simulated_head.hpp"
#include "robogene/can/virtual_bus.hpp"
#include "test_bus_dir.hpp"

namespace robogene::can {
namespace {

constexpr int kEyes = 3;

struct Flashing : ::testing::Test {
  testing::TempBusDir dir;
  HeadConfig head = testing::head_config();
  std::unique_ptr<sim::SimulatedHead> sim;
  std::unique_ptr<Bus> bus = std::make_unique<VirtualBus>("head");
  std::vector<std::string> log;

  void SetUp() override { sim = std::make_unique<sim::SimulatedHead>(head, std::make_unique<VirtualBus>("head"), sim::MotorParameters{}, dir.path()); }
  std::string flash_file() const { return dir.path() + "/board-3-eyes-pan.flash"; }
  FlashOptions options() {
    FlashOptions o;
    o.address = kEyes;
    o.log = [this](const std::string& l) { log.push_back(l); };
    return o;
  }
  static FirmwareImage image(std::uint8_t board, std::uint32_t size = 9000, char revision = board_revision(), std::uint8_t major = 2) {
    return firmware_image_from_bytes(make_stamped_image(board, static_cast<std::uint8_t>(revision), size, major), "test.bin");
  }
  // Whether the board's flash holds exactly `img` (the flash file of the simulated board).
  bool holds(const FirmwareImage& img) const {
    const auto cells = testing::read_file(flash_file());
    return cells.size() >= img.bytes.size() && std::equal(img.bytes.begin(), img.bytes.end(), cells.begin());
  }
  std::optional<BoardIdentity> who() { return identify_board(*bus, kEyes, Millis(500)); }
};

TEST_F(Flashing, AnUpdateWritesTheImageVerifiesItAndTheBoardRunsItsApplicationAgain) {
  ASSERT_FALSE(sim->in_bootloader(kEyes));
  const FirmwareImage img = image(kEyes, 9001, board_revision(), 3);  // not a multiple of 4
  flash_firmware(*bus, img, options());
  EXPECT_TRUE(holds(img));
  EXPECT_FALSE(sim->in_bootloader(kEyes));
  const auto id = who();
  ASSERT_TRUE(id);
  EXPECT_FALSE(id->in_bootloader);
  EXPECT_EQ(id->board_id, kEyes);
  ASSERT_GE(log.size(), 5u);
  EXPECT_EQ(log.front(), "found board 3, revision " + std::string(1, board_revision()) + " at address 3, running firmware 2.2");
  EXPECT_EQ(log[1], "restarting board 3 into its bootloader");
  EXPECT_NE(log.back().find("started: board 3"), std::string::npos) << log.back();
  // The new image starts at the next power-up too: it checks.
  sim->power_cycle(kEyes);
  EXPECT_FALSE(sim->in_bootloader(kEyes));
}

TEST_F(Flashing, WithoutAnAddressTheBoardBuiltForTheImageIsFound) {
  FlashOptions o = options();
  o.address.reset();
  const FirmwareImage img = image(2);
  flash_firmware(*bus, img, o);
  EXPECT_NE(log.front().find("at address 2"), std::string::npos) << log.front();
  EXPECT_FALSE(holds(img)) << "board 3 was not touched";
  const auto boards = find_boards(*bus, Millis(300));
  ASSERT_EQ(boards.size(), 3u);
  EXPECT_EQ(boards[1].address, 2);
}

TEST_F(Flashing, AnImageForAnotherBoardIsRefusedBeforeAnythingIsErased) {
  const auto before = testing::read_file(flash_file());
  try {
    flash_firmware(*bus, image(1), options());
    FAIL() << "an image for board 1 was flashed into board 3";
  } catch (const FlashError& e) {
    EXPECT_EQ(e.step(), "check");
    EXPECT_NE(std::string(e.what()).find("test.bin is built for board 1; the board at address 3 is board 3: wrong board"),
              std::string::npos) << e.what();
  }
  EXPECT_EQ(testing::read_file(flash_file()), before);
  EXPECT_FALSE(sim->in_bootloader(kEyes));
}

TEST_F(Flashing, TheBoardItselfRefusesAnotherBoardsOrRevisionsImageAndCanBeFlashedAfter) {
  FlashOptions o = options();
  o.check_board = false;  // what a host that does not check would send
  for (const auto& [img, status] : {std::make_pair(image(1), std::string("wrong_board")),
                                    std::make_pair(image(kEyes, 9000, 'B'), std::string("wrong_revision"))}) {
    try {
      flash_firmware(*bus, img, o);
      FAIL() << "the board took an image it must refuse (" << status << ")";
    } catch (const FlashError& e) {
      EXPECT_EQ(e.step(), "write");
      EXPECT_NE(std::string(e.what()).find(status), std::string::npos) << e.what();
    }
    const auto id = who();
    ASSERT_TRUE(id);
    EXPECT_TRUE(id->in_bootloader);
    EXPECT_FALSE(id->image_valid);
  }
  const FirmwareImage good = image(kEyes);
  flash_firmware(*bus, good, options());
  EXPECT_TRUE(holds(good));
  EXPECT_FALSE(sim->in_bootloader(kEyes));
}

TEST_F(Flashing, ACorruptedImageFailsTheBoardsVerifyAndIsNeverStarted) {
  FirmwareImage bad = image(kEyes);
  bad.bytes[5000] ^= 0x01;  // changed after stamping; read_firmware_image would refuse the file
  try {
    flash_firmware(*bus, bad, options());
    FAIL() << "a corrupted image was verified";
  } catch (const FlashError& e) {
    EXPECT_EQ(e.step(), "verify");
    EXPECT_NE(std::string(e.what()).find("crc_mismatch"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(sim->in_bootloader(kEyes));
  sim->power_cycle(kEyes);
  EXPECT_TRUE(sim->in_bootloader(kEyes)) << "a reset must not start an image whose CRC fails";
}

TEST_F(Flashing, AnUpdateCutShortLeavesABoardThatBootsIntoItsBootloaderAndASecondUpdateSucceeds) {
  const FirmwareImage img = image(kEyes, 20000);
  FlashOptions o = options();
  struct HostGone {};
  o.progress = [](std::size_t done, std::size_t total) {
    if (done * 5 >= total * 2) throw HostGone{};  // the flasher dies at 40 %
  };
  EXPECT_THROW(flash_firmware(*bus, img, o), HostGone);
  auto id = who();
  ASSERT_TRUE(id);
  EXPECT_TRUE(id->in_bootloader);
  EXPECT_FALSE(id->image_valid);
  sim->power_cycle(kEyes);  // and the power goes too
  EXPECT_TRUE(sim->in_bootloader(kEyes));
  id = who();
  ASSERT_TRUE(id);
  EXPECT_TRUE(id->in_bootloader) << "the board answers from its bootloader after a reset";
  flash_firmware(*bus, img, options());
  EXPECT_TRUE(holds(img));
  EXPECT_FALSE(sim->in_bootloader(kEyes));
  sim->power_cycle(kEyes);
  EXPECT_FALSE(sim->in_bootloader(kEyes));
}

TEST_F(Flashing, LostWritesAndLostAcknowledgementsAreSentAgain) {
  int writes = 0;
  testing::LossyBus lossy(std::make_unique<VirtualBus>("head"), [&](const Frame& f, int) {
    // Every 37th write frame never reaches the board.
    return (f.id >> 8) == 7 && f.len == 7 && f.data[0] == 3 && ++writes % 37 == 0;
  });
  const FirmwareImage img = image(kEyes, 12000);
  FlashOptions o = options();
  o.reply_timeout = Millis(100);
  flash_firmware(lossy, img, o);
  EXPECT_GT(writes, 3000);
  EXPECT_TRUE(holds(img));
  EXPECT_FALSE(sim->in_bootloader(kEyes));
}

TEST_F(Flashing, SilenceIsATimeoutNamingTheStep) {
  FlashOptions o = options();
  o.address = 9;  // no board there
  o.reply_timeout = Millis(100);
  try {
    flash_firmware(*bus, image(kEyes), o);
    FAIL();
  } catch (const FlashError& e) {
    EXPECT_EQ(e.step(), "find");
    EXPECT_NE(std::string(e.what()).find("no board answered bootloader_identify at address 9 within 100 ms"), std::string::npos)
        << e.what();
  }
  // The bus goes quiet once the erase is answered: the write step times out and says where.
  bool erased = false;
  testing::LossyBus dead(std::make_unique<VirtualBus>("head"), [&](const Frame& f, int) {
    if ((f.id >> 8) == 7 && f.data[0] == 2) {
      erased = true;
      return false;
    }
    return erased;
  });
  o.address = kEyes;
  try {
    flash_firmware(dead, image(kEyes), o);
    FAIL();
  } catch (const FlashError& e) {
    EXPECT_EQ(e.step(), "write");
    EXPECT_NE(std::string(e.what()).find("no acknowledgement of word 0 (byte 0 of 9000) after 6 tries of 100 ms"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(sim->in_bootloader(kEyes));
}

}  // namespace
}  // namespace robogene::can
