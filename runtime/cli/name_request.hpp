// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// One raw request to the name server as YARP's own tools send it (`NAME_SERVER <words>\n` on a
// fresh connection), returning the reply lines. Used by `robogene name`, which prints them.
#pragma once

#include <string>
#include <vector>

#include "robogene/net/endpoint.hpp"

namespace robogene::cli {

struct NameServerReply {
  std::vector<std::string> lines;  // without "\r\n", "*** end of message" excluded
  bool ended = false;              // "*** end of message" was seen (old-style reply)
  std::string error;               // text of a "*** error: ..." line, if any
};

// Throws robogene::Error naming the server address when it cannot be reached or does not answer.
NameServerReply name_request(const net::Endpoint& server, const std::string& request);

}  // namespace robogene::cli
