// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// How /root answers the messages of one inbound connection, whatever its carrier: requests ('d',
// 'D') go to the NameService, plus the port commands every port answers (admin 'a', describe
// '*', help '?'). Private to src/name.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "robogene/carrier/connection.hpp"
#include "robogene/name/name_server.hpp"
#include "robogene/name/name_service.hpp"

namespace robogene::name::detail {

struct RootPortContext {
  NameService& service;
  std::string peer_host;     // IP of the other side, for `register` without an address
  std::string root_address;  // "tcp://127.0.0.1:10000/"
  std::function<std::vector<NameServer::Peer>()> peers;
  std::function<void()> heard;  // called as each message arrives (idle tracking); may be empty
};

// Serves messages until the peer closes or sends 'q'. Throws NetworkError / ParseError when the
// connection breaks its carrier's framing (the caller logs it and closes).
void serve_root_messages(RootPortContext& c, carrier::InboundConnection& in);

}  // namespace robogene::name::detail
