// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A motor board's application image as `make firmware` writes it (build/fab/firmware/
// robogene-motor-board-*.bin or .hex): the bytes of the application region from its vector
// table, with the header the build stamps (hardware/electronics/firmware/core/rg_image.h). Read
// and checked here with the firmware's own C code, the way the bootloader checks it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "robogene/error.hpp"

namespace robogene::can {

// Where the application region starts on the STM32G431 and how big it is (docs/firmware.md).
inline constexpr std::uint32_t kApplicationBase = 0x08004000u;
inline constexpr std::uint32_t kApplicationRegionBytes = 110u * 1024u;

class FirmwareImageError : public Error {
 public:
  using Error::Error;
};

struct FirmwareImage {
  std::string source;                // the file, for messages
  std::vector<std::uint8_t> bytes;   // from the application region's first byte
  std::uint32_t size = 0, crc = 0;   // the header's
  std::uint8_t board_type = 0, board_id = 0, revision = 0;
  std::uint8_t version_major = 0, version_minor = 0, version_build = 0;
};

// Reads a .bin (the region's bytes) or an Intel HEX file (.hex; records inside the application
// region). Throws FirmwareImageError naming the file and what is wrong: unreadable, a malformed
// HEX line (by number) or a record outside the region, no image header (not built by `make
// firmware`), a header whose size is not the file's, a CRC-32 that does not match the bytes.
FirmwareImage read_firmware_image(const std::string& path);
// The same checks on bytes already in memory; `source` names them in messages.
FirmwareImage firmware_image_from_bytes(std::vector<std::uint8_t> bytes, const std::string& source);

// `size` bytes stamped for a board as the build stamps an image, with filler for code: the
// simulator's flash holds one at first power-up (it runs the control core natively), and tests
// flash them.
std::vector<std::uint8_t> make_stamped_image(std::uint8_t board_id, std::uint8_t revision, std::uint32_t size,
                                             std::uint8_t version_major = 2, std::uint8_t version_minor = 0);

// The revision this build's firmware and simulator are for (the board's, an ASCII letter).
char board_revision();

// "board 3, revision C, firmware 2.0.0, 10912 bytes, CRC-32 0x495A7594"
std::string describe(const FirmwareImage& image);

}  // namespace robogene::can
