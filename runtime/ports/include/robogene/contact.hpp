// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Where a port lives (YARP's Contact): its name, the carrier it registered, host and number.
// Also parses the connection targets users and `yarp connect` write: "/r", "tcp://r"
// (= carrier "tcp" + ":/" + "/r"), "udp://mc/stateExt:i".
#pragma once

#include <string>
#include <string_view>

#include "robogene/net/endpoint.hpp"

namespace robogene {

struct Contact {
  std::string name;            // "/r"
  std::string carrier = "tcp";
  std::string host;            // "127.0.0.1"
  int port = 0;

  net::Endpoint endpoint() const { return {host, port}; }
  // "tcp://127.0.0.1:10003/" as YARP prints a port's address.
  std::string uri() const { return carrier + "://" + host + ":" + std::to_string(port) + "/"; }
};

// A connection target: the port name and the carrier asked for ("" = the port's own).
struct Target {
  std::string name;
  std::string carrier;
};

// Splits "tcp://r" into {"/r", "tcp"} and "/r" into {"/r", ""}. Throws robogene::Error naming the
// text when it is not a port name ("r", "", "tcp:/" ...).
Target parse_target(std::string_view text);

}  // namespace robogene
