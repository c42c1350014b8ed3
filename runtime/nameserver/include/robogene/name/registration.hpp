// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// One entry of the name server: where a port can be reached (YARP's Contact, as stored by
// yarpserver: name, carrier, host, socket number and optional type).
#pragma once

#include <string>

namespace robogene::name {

struct Registration {
  std::string name;     // "/motors/rpc:i"
  std::string carrier;  // "tcp", "mcast", ...
  std::string host;     // "127.0.0.1"
  int port = 0;         // TCP port number (or mcast group port)
  std::string type;     // "*" when none was given
  double registered_at = 0;  // seconds since the epoch, used for the stale-check grace period

  bool operator==(const Registration& o) const {
    return name == o.name && carrier == o.carrier && host == o.host && port == o.port && type == o.type;
  }
};

}  // namespace robogene::name
