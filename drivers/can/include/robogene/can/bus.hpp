// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Bus: one node's view of a CAN bus. Every node sees every other node's frames, never its own
// (SocketCAN's default). Errors the controller reports arrive as BusError from receive(), and a
// frame that cannot be sent throws from send(): nothing is hidden from the caller.
//
// Backends are named by a spec: "socketcan:vcan0" (Linux SocketCAN, raw socket) or
// "virtual:NAME" (a bus between processes of one machine; see virtual_bus.hpp).
// send() and receive() may be called from different threads at once.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "robogene/can/bus_error.hpp"
#include "robogene/can/frame.hpp"

namespace robogene::can {

using Millis = std::chrono::milliseconds;

class Bus {
 public:
  virtual ~Bus() = default;

  // Queues one frame for the bus. Throws BusError: `timeout` when the controller cannot take it
  // within `timeout`, `io` when the interface is down or refuses it, and robogene::Error for an
  // invalid frame.
  virtual void send(const Frame& frame, Millis timeout) = 0;

  // The next frame from another node that passes the filters, or nullopt when none came within
  // `timeout`. Throws BusError when the controller reports an error (bus-off, error-passive...).
  virtual std::optional<Frame> receive(Millis timeout) = 0;

  // Frames whose id matches none of `filters` are dropped (an empty list passes everything).
  // Error reports are never filtered out.
  virtual void set_filters(const std::vector<Filter>& filters) = 0;

  // The spec it was opened with ("socketcan:vcan0"), for messages and logs.
  virtual std::string name() const = 0;
  // The interface name candump would print ("vcan0", or the virtual bus's name).
  virtual std::string interface() const = 0;
};

// Opens a bus from its spec. Throws robogene::Error naming the spec and what is wrong with it
// (unknown backend, bad name), or BusError(io) when the system refuses (no such interface,
// no CAN support in the kernel).
std::unique_ptr<Bus> open_bus(const std::string& spec);

}  // namespace robogene::can
