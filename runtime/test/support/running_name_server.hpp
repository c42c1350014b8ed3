// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A real name server (in-memory registry) on an ephemeral loopback port, for tests of ports and
// carriers that need one (mcast asks it for a multicast group).
#pragma once

#include <thread>

#include "robogene/name/name_server.hpp"
#include "robogene/name/name_service.hpp"
#include "robogene/name/registry.hpp"
#include "robogene/name_client.hpp"
#include "robogene/net/tcp_listener.hpp"

namespace robogene::test {

struct RunningNameServer {
  name::Registry registry{":memory:"};
  net::TcpListener listener = net::TcpListener::listen({"127.0.0.1", 0});
  int port = listener.local().port;
  name::NameService service{registry,
                            [this] {
                              name::NameServiceConfig c;
                              c.port = port;
                              return c;
                            }(),
                            nullptr};
  name::NameServer server{service, std::move(listener)};
  std::thread thread{[this] { server.run(); }};

  ~RunningNameServer() {
    server.stop();
    thread.join();
  }
  net::Endpoint at() const { return {"127.0.0.1", port}; }
  NameClient client() const { return NameClient(at()); }
};

}  // namespace robogene::test
