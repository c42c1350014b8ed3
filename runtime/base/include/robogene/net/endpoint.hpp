// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Where a socket is: an IPv4 host (dotted quad or name) and a port number.
#pragma once

#include <string>

namespace robogene::net {

struct Endpoint {
  std::string host;  // "127.0.0.1"
  int port = 0;

  std::string to_string() const { return host + ":" + std::to_string(port); }
  bool operator==(const Endpoint& o) const { return host == o.host && port == o.port; }
};

}  // namespace robogene::net
