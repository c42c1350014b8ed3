// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene can-flash`: update a motor board's application over CAN through its bootloader
// (docs/firmware.md#updating-over-can). The image is checked before the bus is touched (its
// stamped header and CRC), the board found and checked against it before anything is erased.
#include <cstdio>
#include <cstdlib>

#include "commands.hpp"
#include "robogene/can/firmware_image.hpp"
#include "robogene/can/flasher.hpp"

namespace robogene::cli {

int cmd_can_flash(Args& args) {
  const auto bus_spec = args.option("--bus");
  const auto address = args.option("--address");
  const auto timeout = args.option("--timeout");
  const bool no_start = args.flag("--no-start");
  const std::vector<std::string> files = args.positional();
  if (!bus_spec) throw UsageError("--bus is required (virtual:NAME or socketcan:IFACE)");
  if (files.size() != 1) throw UsageError("give one image: build/fab/firmware/robogene-motor-board-<address>-<name>.bin or .hex");

  can::FlashOptions options;
  if (address) {
    char* end = nullptr;
    const long a = std::strtol(address->c_str(), &end, 10);
    if (end == address->c_str() || *end != '\0') throw UsageError("--address " + *address + ": not a number");
    options.address = static_cast<int>(a);
  }
  if (timeout) options.reply_timeout = can::Millis(static_cast<long>(parse_seconds(*timeout, "--timeout") * 1000.0));
  options.start = !no_start;
  options.log = [](const std::string& line) {
    std::printf("can-flash: %s\n", line.c_str());
    std::fflush(stdout);
  };
  int last_tenth = -1;
  options.progress = [&last_tenth](std::size_t done, std::size_t total) {
    const int tenth = static_cast<int>(done * 10 / total);
    if (tenth == last_tenth) return;
    last_tenth = tenth;
    std::printf("can-flash: written %zu of %zu bytes (%d %%)\n", done, total, tenth * 10);
    std::fflush(stdout);
  };

  const can::FirmwareImage image = can::read_firmware_image(files[0]);
  std::printf("can-flash: %s: %s\n", files[0].c_str(), can::describe(image).c_str());
  std::fflush(stdout);
  const auto bus = can::open_bus(*bus_spec);
  try {
    can::flash_firmware(*bus, image, options);
  } catch (const can::FlashError& e) {
    std::fprintf(stderr, "robogene can-flash: %s\n", e.what());
    return 1;
  }
  std::printf("can-flash: done\n");
  return 0;
}

}  // namespace robogene::cli
