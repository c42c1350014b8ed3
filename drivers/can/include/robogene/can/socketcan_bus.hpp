// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// SocketCAN backend: a raw PF_CAN socket bound to one interface (can0, vcan0...). Data filters
// go to the kernel as CAN_RAW_FILTER (standard frames only), and every error class is enabled
// with CAN_RAW_ERR_FILTER so bus-off, error-passive and friends reach the caller as BusError.
#pragma once

#include <mutex>
#include <string>

#include "robogene/can/bus.hpp"

namespace robogene::can {

class SocketCanBus final : public Bus {
 public:
  // Throws BusError(io) naming the interface when the kernel has no CAN, the interface is
  // missing, or the socket cannot be bound.
  explicit SocketCanBus(const std::string& interface);
  ~SocketCanBus() override;
  SocketCanBus(const SocketCanBus&) = delete;
  SocketCanBus& operator=(const SocketCanBus&) = delete;

  void send(const Frame& frame, Millis timeout) override;
  std::optional<Frame> receive(Millis timeout) override;
  void set_filters(const std::vector<Filter>& filters) override;
  std::string name() const override { return "socketcan:" + interface_; }
  std::string interface() const override { return interface_; }

 private:
  [[noreturn]] void fail(const std::string& doing, int err) const;

  std::string interface_;
  int fd_ = -1;
};

}  // namespace robogene::can
