// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/rpc.hpp"

#include "robogene/error.hpp"

namespace robogene {

void RpcClient::connect(const std::string& server, const std::string& carrier) {
  if (!server_.empty()) port_.remove_output(server_);
  port_.add_output(server, carrier);
  server_ = parse_target(server).name;
}

void RpcClient::connect(const Contact& server) {
  if (!server_.empty()) port_.remove_output(server_);
  port_.add_output(server);
  server_ = server.name;
}

Bottle RpcClient::call(const Bottle& request) {
  Bottle reply;
  if (!port_.write(request, reply)) {
    throw NetworkError(server_.empty() ? "rpc client " + port_.name() + " is not connected"
                                       : "rpc call from " + port_.name() + " to " + server_ +
                                             " failed (connection dropped; see the log)");
  }
  return reply;
}

void RpcServer::serve(Handler h) {
  port_.set_reader([h = std::move(h)](const Bottle& b, const MessageInfo& info, Bottle* reply) {
    Bottle r = h(b, info);
    if (reply) *reply = std::move(r);
  });
}

}  // namespace robogene
