// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A real name server on 127.0.0.1 (ephemeral port, in memory) for the network wrapper tests,
// and configurations that point devices at it.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <thread>

#include "robogene/bottle.hpp"
#include "robogene/dev/property.hpp"
#include "robogene/name/name_server.hpp"
#include "robogene/name/name_service.hpp"
#include "robogene/name/registry.hpp"
#include "robogene/name_client.hpp"
#include "robogene/net/tcp_listener.hpp"

namespace robogene::test {

struct LocalNameServer {
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

  ~LocalNameServer() {
    server.stop();
    thread.join();
  }
  std::string address() const { return "127.0.0.1:" + std::to_string(port); }
  NameClient client() const { return NameClient(net::Endpoint{"127.0.0.1", port}); }

  // A device configuration from text ("(device test_motor) (axes 2)") using this server.
  dev::Property config(const std::string& text) const {
    dev::Property p = dev::Property::from_bottle(Bottle::from_text(text), "test configuration");
    p.put("server", Value::string(address()));
    return p;
  }
};

// Polls `done` until it holds or `seconds` pass.
inline bool eventually(const std::function<bool()>& done, double seconds = 5.0) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < until) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return done();
}

}  // namespace robogene::test
