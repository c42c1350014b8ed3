// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/bus.hpp"
#include "robogene/can/socketcan_bus.hpp"
#include "robogene/can/virtual_bus.hpp"

namespace robogene::can {

std::unique_ptr<Bus> open_bus(const std::string& spec) {
  const auto colon = spec.find(':');
  const std::string backend = spec.substr(0, colon);
  const std::string rest = colon == std::string::npos ? "" : spec.substr(colon + 1);
  if (colon == std::string::npos || rest.empty() || (backend != "socketcan" && backend != "virtual")) {
    throw Error("CAN bus \"" + spec + "\": expected socketcan:IFACE (e.g. socketcan:vcan0) or virtual:NAME");
  }
  if (backend == "socketcan") return std::make_unique<SocketCanBus>(rest);
  return std::make_unique<VirtualBus>(rest);
}

}  // namespace robogene::can
