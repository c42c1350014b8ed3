// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The bootloader's state machine on a fake flash with the STM32G431's rules: 2 KiB pages erased to
// 0xFF, programming 8 bytes at a time only into erased cells (a second write to a cell is an
// error, as PROGERR on the part), failures on demand; and a stamped image built as the firmware's
// build stamps one (tools/stamp_image.py).
#pragma once

#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "rg_boot.h"
#include "rg_crc32.h"
#include "rg_image.h"
#include "generated/robogene_can_motor_control.h"

namespace rg_test {

struct FakeFlash {
  static constexpr std::uint32_t kPage = 2048, kRegion = 110 * 1024;
  std::vector<std::uint8_t> cells = std::vector<std::uint8_t>(kRegion, 0xFF);
  std::vector<bool> programmed = std::vector<bool>(kRegion / 8, false);
  std::optional<std::uint32_t> fail_program_at, fail_erase_page;
  int erases = 0, programs = 0, starts = 0;
  std::vector<rg_can_frame_t> sent;
  rg_boot_hal_t hal{};

  static FakeFlash& of(void* ctx) { return *static_cast<FakeFlash*>(ctx); }

  FakeFlash() {
    hal.ctx = this;
    hal.region_size = kRegion;
    hal.page_size = kPage;
    hal.erase_page = [](void* ctx, std::uint32_t page) {
      FakeFlash& f = of(ctx);
      if (f.fail_erase_page && *f.fail_erase_page == page) return false;
      if ((page + 1) * kPage > kRegion) return false;
      std::memset(f.cells.data() + page * kPage, 0xFF, kPage);
      for (std::uint32_t u = page * kPage / 8; u < (page + 1) * kPage / 8; ++u) f.programmed[u] = false;
      ++f.erases;
      return true;
    };
    hal.program = [](void* ctx, std::uint32_t offset, const std::uint8_t* data) {
      FakeFlash& f = of(ctx);
      if (offset % 8 != 0 || offset + 8 > kRegion || f.programmed[offset / 8]) return false;
      if (f.fail_program_at && *f.fail_program_at == offset) return false;
      std::memcpy(f.cells.data() + offset, data, 8);
      f.programmed[offset / 8] = true;
      ++f.programs;
      return true;
    };
    hal.read = [](void* ctx, std::uint32_t offset, std::uint8_t* out, std::uint32_t len) {
      FakeFlash& f = of(ctx);
      if (offset + len > kRegion) return false;
      std::memcpy(out, f.cells.data() + offset, len);
      return true;
    };
    hal.can_send = [](void* ctx, const rg_can_frame_t* frame) {
      of(ctx).sent.push_back(*frame);
      return true;
    };
    hal.start_application = [](void* ctx) { ++of(ctx).starts; };
  }
};

inline void put32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) b[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}

// An image of `size` bytes for `board_id` and `revision`, its header stamped as the build does.
inline std::vector<std::uint8_t> stamped_image(std::uint32_t size, std::uint8_t board_id, std::uint8_t revision = 'C',
                                               std::uint8_t board_type = ROBOGENE_CAN_BOARD_TYPE_ROBOGENE_MOTOR_BOARD) {
  std::vector<std::uint8_t> img(size);
  for (std::uint32_t i = 0; i < size; ++i) img[i] = static_cast<std::uint8_t>(i * 7 + 3);
  const std::size_t h = RG_IMAGE_HEADER_OFFSET;
  std::memset(img.data() + h, 0, RG_IMAGE_HEADER_SIZE);
  put32(img, h + RG_IMAGE_MAGIC_AT, RG_IMAGE_MAGIC);
  put32(img, h + RG_IMAGE_SIZE_AT, size);
  img[h + RG_IMAGE_HEADER_VERSION_AT] = RG_IMAGE_HEADER_VERSION;
  img[h + RG_IMAGE_BOARD_TYPE_AT] = board_type;
  img[h + RG_IMAGE_BOARD_ID_AT] = board_id;
  img[h + RG_IMAGE_REVISION_AT] = revision;
  img[h + RG_IMAGE_VERSION_AT] = 2;
  put32(img, h + RG_IMAGE_CRC_AT, rg_crc32(0, img.data(), img.size()));  // the crc field is zero here
  return img;
}

}  // namespace rg_test
