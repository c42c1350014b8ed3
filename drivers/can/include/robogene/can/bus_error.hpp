// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// What a bus reports when something is wrong on it. Controllers report trouble as error frames
// (Linux linux/can/error.h); both backends decode the same encoding, so a virtual bus can inject
// the bus-off or error-passive a real controller would raise, and the driver handles both alike.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "robogene/can/frame.hpp"
#include "robogene/error.hpp"

namespace robogene::can {

enum class BusErrorKind {
  timeout,           // a send or an expected reply did not happen in time
  bus_off,           // the controller left the bus (too many errors)
  error_passive,     // the controller's error counters passed 127
  error_warning,     // the controller's error counters passed 96
  no_ack,            // nobody acknowledged a frame (no other node, or a broken bus)
  tx_timeout,        // the controller could not send in time
  lost_arbitration,  // the controller lost arbitration
  protocol,          // a protocol violation (stuff, form, bit error)
  transceiver,       // wiring trouble (CAN_H/CAN_L short or open)
  restarted,         // the controller came back after bus-off
  controller,        // another controller problem (overflow...)
  io,                // the operating system refused (socket, interface down...)
};

const char* name_of(BusErrorKind k) noexcept;

// The raw form of an error frame, as SocketCAN delivers it: a 29-bit class mask with
// CAN_ERR_FLAG set, and 8 data bytes of details.
struct ErrorFrame {
  std::uint32_t can_id = 0;  // CAN_ERR_FLAG | CAN_ERR_* class bits
  std::array<std::uint8_t, 8> data{};
};

class BusError : public Error {
 public:
  BusError(BusErrorKind kind, const std::string& what) : Error(what), kind_(kind) {}
  BusError(BusErrorKind kind, const std::string& what, const ErrorFrame& frame)
      : Error(what), kind_(kind), frame_(frame) {}
  BusErrorKind kind() const noexcept { return kind_; }
  // The error frame this error was decoded from, when a controller reported it.
  const std::optional<ErrorFrame>& frame() const noexcept { return frame_; }

 private:
  BusErrorKind kind_;
  std::optional<ErrorFrame> frame_;
};

constexpr std::uint32_t kErrFlag = 0x20000000U;  // CAN_ERR_FLAG

// The most serious condition an error frame reports, with a message naming the bus and every
// class bit set.
BusError decode_error_frame(const std::string& bus, const ErrorFrame& e);

// The error frame a controller would send for `kind` (for the virtual backend and tests).
ErrorFrame make_error_frame(BusErrorKind kind);

}  // namespace robogene::can
