// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// For the firmware-update tests: image files as `make firmware` writes them (.bin, and .hex as
// objcopy writes it), and a bus that loses frames on purpose.
#pragma once

#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "robogene/can/bus.hpp"
#include "robogene/can/firmware_image.hpp"

namespace robogene::can::testing {

inline void write_file(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

inline std::vector<std::uint8_t> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<std::uint8_t>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Intel HEX of `bytes` at `base`, 16 bytes a record, as arm-none-eabi-objcopy -O ihex writes it.
inline std::string to_intel_hex(const std::vector<std::uint8_t>& bytes, std::uint32_t base) {
  std::string out;
  auto record = [&](std::uint8_t type, std::uint16_t offset, const std::uint8_t* data, std::size_t n) {
    char buf[16];
    std::uint8_t sum = static_cast<std::uint8_t>(n + (offset >> 8) + (offset & 0xFF) + type);
    std::snprintf(buf, sizeof buf, ":%02X%04X%02X", static_cast<unsigned>(n), offset, type);
    out += buf;
    for (std::size_t i = 0; i < n; ++i) {
      std::snprintf(buf, sizeof buf, "%02X", data[i]);
      out += buf;
      sum = static_cast<std::uint8_t>(sum + data[i]);
    }
    std::snprintf(buf, sizeof buf, "%02X\n", static_cast<std::uint8_t>(-sum) & 0xFF);
    out += buf;
  };
  std::uint32_t upper = 0xFFFFFFFF;
  for (std::size_t at = 0; at < bytes.size(); at += 16) {
    const std::uint32_t address = base + static_cast<std::uint32_t>(at);
    if ((address >> 16) != upper) {
      upper = address >> 16;
      const std::uint8_t ela[2] = {static_cast<std::uint8_t>(upper >> 8), static_cast<std::uint8_t>(upper)};
      record(0x04, 0, ela, 2);
    }
    record(0x00, static_cast<std::uint16_t>(address & 0xFFFF), bytes.data() + at, std::min<std::size_t>(16, bytes.size() - at));
  }
  record(0x01, 0, nullptr, 0);
  return out;
}

// A bus that passes frames through, except those `drop` says to lose (counted by direction).
class LossyBus : public Bus {
 public:
  LossyBus(std::unique_ptr<Bus> inner, std::function<bool(const Frame&, int sent_count)> drop)
      : inner_(std::move(inner)), drop_(std::move(drop)) {}
  void send(const Frame& f, Millis t) override {
    if (drop_(f, ++sent_)) return;
    inner_->send(f, t);
  }
  std::optional<Frame> receive(Millis t) override { return inner_->receive(t); }
  void set_filters(const std::vector<Filter>& f) override { inner_->set_filters(f); }
  std::string name() const override { return inner_->name(); }
  std::string interface() const override { return inner_->interface(); }

 private:
  std::unique_ptr<Bus> inner_;
  std::function<bool(const Frame&, int)> drop_;
  int sent_ = 0;
};

}  // namespace robogene::can::testing
