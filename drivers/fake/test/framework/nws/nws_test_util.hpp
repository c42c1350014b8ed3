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
#include "robogene/name/local_name_server.hpp"

namespace robogene::test {

// The library's in-process name server, and configurations that point devices at it.
struct LocalNameServer : name::LocalNameServer {
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
