// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// One inbound connection of the name server, per carrier (private to src/name).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "robogene/name/name_server.hpp"
#include "robogene/name/name_service.hpp"
#include "robogene/net/stream_reader.hpp"
#include "robogene/net/tcp_stream.hpp"
#include "yarp_wire.hpp"

namespace robogene::name::detail {

struct SessionContext {
  NameService& service;
  const NameServerLimits& limits;
  net::TcpStream& stream;
  net::StreamReader& reader;
  std::string root_address;                             // "tcp://127.0.0.1:10000/"
  std::function<void(const std::string& name, const std::string& carrier)> identify;
  std::function<std::vector<NameServer::Peer>()> peers;
  void log(const std::string& what) const;
};

// `header` holds the 8 bytes already read; each returns when the peer is done or misbehaves
// (after telling it why when the carrier lets us).
void serve_name_ser(SessionContext& c, const wire::Header& header);
void serve_text(SessionContext& c, bool with_acks);
void serve_tcp(SessionContext& c, bool with_acks);
void refuse_unknown_carrier(SessionContext& c, const wire::Header& header);

}  // namespace robogene::name::detail
