// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Updating a motor board's application over the bus through its bootloader (the protocol's
// bootloader class, docs/firmware.md#updating-over-can): find the board, check the image was built
// for it, restart it into its bootloader, erase, write the image four bytes a frame with a few
// writes in flight (each acknowledged by sequence number, lost ones sent again), verify the CRC
// the board computes, start the new application and see it answer. `robogene can-flash` is this.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "robogene/can/bus.hpp"
#include "robogene/can/firmware_image.hpp"
#include "robogene/error.hpp"

namespace robogene::can {

// A failed update; the message names the step (find, check, enter, erase, write, verify, start)
// and what the board answered or that it did not answer in time.
class FlashError : public Error {
 public:
  FlashError(std::string step, const std::string& what) : Error(step + ": " + what), step_(std::move(step)) {}
  const std::string& step() const { return step_; }

 private:
  std::string step_;
};

struct BoardIdentity {
  int address = 0;
  std::uint8_t board_type = 0, board_id = 0, revision = 0;
  bool in_bootloader = false, image_valid = false;
  std::uint8_t version_major = 0, version_minor = 0;
};

std::string describe(const BoardIdentity& board);

struct FlashOptions {
  std::optional<int> address;            // the board's CAN address; unset: the one built for the image's board
  Millis reply_timeout{300};             // identify, write, start
  Millis erase_timeout{5000};            // page erases take about 22 ms each on the part
  Millis verify_timeout{3000};           // a CRC-32 over up to 110 KiB on the bootloader's 16 MHz clock
  Millis enter_timeout{3000};            // until the bootloader (or the new application) answers
  int window = 3;                        // writes in flight: the board's receive FIFO holds 3 frames
  int retries = 5;                       // resends of a write nobody acknowledged
  bool check_board = true;               // refuse an image for another board before erasing anything
  bool start = true;                     // start the application once it verified
  std::function<void(const std::string&)> log;                        // one line per step
  std::function<void(std::size_t done, std::size_t total)> progress;  // bytes acknowledged
};

// Every board that answers bootloader_identify at the broadcast address within `wait`.
std::vector<BoardIdentity> find_boards(Bus& bus, Millis wait);
// One board's identity; nullopt when it did not answer within `timeout`.
std::optional<BoardIdentity> identify_board(Bus& bus, int address, Millis timeout);

// Runs the update; throws FlashError. On any failure after the erase the board is left in its
// bootloader with no valid image (it will not start a partial image) and can be flashed again.
void flash_firmware(Bus& bus, const FirmwareImage& image, const FlashOptions& options);

}  // namespace robogene::can
