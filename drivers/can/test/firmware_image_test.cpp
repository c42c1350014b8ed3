// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Reading an application image the way `robogene can-flash` does before it touches the bus: a
// .bin or a .hex, checked with the firmware's own header and CRC code; each defect named.
#include <gtest/gtest.h>

#include "flash_fixture.hpp"
#include "robogene/can/firmware_image.hpp"
#include "test_bus_dir.hpp"

namespace robogene::can {
namespace {

std::string refusal(const std::string& path) {
  try {
    read_firmware_image(path);
  } catch (const FirmwareImageError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(FirmwareImage, BinAndHexOfOneImageReadTheSame) {
  testing::TempBusDir dir;
  const auto bytes = make_stamped_image(3, 'C', 5001, 2, 1);
  testing::write_file(dir.path() + "/a.bin", bytes);
  std::ofstream(dir.path() + "/a.hex") << testing::to_intel_hex(bytes, kApplicationBase);
  const FirmwareImage bin = read_firmware_image(dir.path() + "/a.bin");
  const FirmwareImage hex = read_firmware_image(dir.path() + "/a.hex");
  EXPECT_EQ(bin.bytes, bytes);
  EXPECT_EQ(hex.bytes, bytes);
  EXPECT_EQ(bin.board_id, 3);
  EXPECT_EQ(bin.revision, 'C');
  EXPECT_EQ(bin.size, 5001u);
  EXPECT_EQ(describe(bin).substr(0, 51), "board 3, revision C, firmware 2.1.0, 5001 bytes, CR");
}

TEST(FirmwareImage, DefectsAreNamedWithTheFile) {
  testing::TempBusDir dir;
  const std::string d = dir.path();
  auto bytes = make_stamped_image(3, 'C', 4096);
  auto corrupted = bytes;
  corrupted[3000] ^= 0x80;
  testing::write_file(d + "/corrupted.bin", corrupted);
  EXPECT_NE(refusal(d + "/corrupted.bin").find("corrupted.bin: CRC-32 mismatch: the header says 0x"), std::string::npos)
      << refusal(d + "/corrupted.bin");
  testing::write_file(d + "/short.bin", std::vector<std::uint8_t>(bytes.begin(), bytes.end() - 100));
  EXPECT_NE(refusal(d + "/short.bin").find("short.bin: the header says 4096 bytes, the file holds 3996"), std::string::npos);
  auto raw = bytes;
  raw[0x200] = 0;
  testing::write_file(d + "/raw.bin", raw);
  EXPECT_NE(refusal(d + "/raw.bin").find("raw.bin: no image header at offset 0x200"), std::string::npos);
  EXPECT_NE(refusal(d + "/missing.bin").find("missing.bin: cannot open the image"), std::string::npos);
  EXPECT_NE(refusal(d + "/x.elf").find("cannot open"), std::string::npos);
  std::ofstream(d + "/y.elf") << "ELF";
  EXPECT_NE(refusal(d + "/y.elf").find("give the .bin or .hex"), std::string::npos);

  std::string hex = testing::to_intel_hex(bytes, kApplicationBase);
  std::string bad_sum = hex;
  bad_sum[bad_sum.find('\n', 20) - 1] ^= 1;  // the second record's checksum
  std::ofstream(d + "/sum.hex") << bad_sum;
  EXPECT_NE(refusal(d + "/sum.hex").find("sum.hex:2: checksum does not match"), std::string::npos) << refusal(d + "/sum.hex");
  std::ofstream(d + "/boot.hex") << testing::to_intel_hex(bytes, 0x08000000);
  EXPECT_NE(refusal(d + "/boot.hex").find("boot.hex:2: data at 0x08000000 is outside the application region"), std::string::npos)
      << refusal(d + "/boot.hex");
  std::ofstream(d + "/cut.hex") << hex.substr(0, hex.rfind(":00000001FF"));
  EXPECT_NE(refusal(d + "/cut.hex").find("cut.hex: no end-of-file record"), std::string::npos) << refusal(d + "/cut.hex");
}

}  // namespace
}  // namespace robogene::can
