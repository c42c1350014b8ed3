// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A simulated board's application region of flash, with the STM32G431's rules (2 KiB pages erased
// to 0xFF, 8 bytes programmed at a time and only into erased cells), behind the bootloader's flash
// HAL. Kept in memory, or in a file so that it survives the simulator's restarts (a power cycle
// of the simulated head): `robogene can-sim --flash-dir DIR`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace robogene::can::sim {

class SimFlash {
 public:
  static constexpr std::uint32_t kPageBytes = 2048;

  // A region of `size` bytes. With a `path`: read from it when it exists (it must hold exactly
  // `size` bytes), else created with `initial`; every erase and write goes to it at once. Throws
  // robogene::Error naming the file when it cannot be read or written.
  SimFlash(std::uint32_t size, const std::vector<std::uint8_t>& initial, std::string path = {});
  ~SimFlash();
  SimFlash(const SimFlash&) = delete;
  SimFlash& operator=(const SimFlash&) = delete;

  std::uint32_t size() const { return static_cast<std::uint32_t>(cells_.size()); }
  bool erase_page(std::uint32_t page);
  bool program(std::uint32_t offset, const std::uint8_t* data);  // 8 bytes
  bool read(std::uint32_t offset, std::uint8_t* out, std::uint32_t len) const;

 private:
  void store(std::uint32_t offset, std::uint32_t len);

  std::vector<std::uint8_t> cells_;
  std::string path_;
  int fd_ = -1;
};

}  // namespace robogene::can::sim
