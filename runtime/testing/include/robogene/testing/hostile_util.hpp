// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Shared by the hostile-peer tests: limits set for one test, raw handshakes as an attacker
// sends them, and the legitimate client that must still be served after each attack.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "robogene/testing/process_usage.hpp"
#include "robogene/testing/port_test_util.hpp"
#include "robogene/testing/wire_helpers.hpp"
#include "robogene/bottle.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/limits.hpp"
#include "robogene/port.hpp"

namespace robogene::test {

// The process-wide handshake-deadline timer: one thread, started by the first handshake and
// kept, so a test that measures before the first handshake sees it appear.
constexpr std::size_t kDeadlineTimerThread = 1;

// Limits changed for the length of one test.
class ScopedLimits {
 public:
  explicit ScopedLimits(const ResourceLimits& l) : saved_(resource_limits()) { set_resource_limits(l); }
  ~ScopedLimits() { set_resource_limits(saved_); }
  ScopedLimits(const ScopedLimits&) = delete;
  ScopedLimits& operator=(const ScopedLimits&) = delete;

 private:
  ResourceLimits saved_;
};

// A carrier header followed by a sender name, as every binary carrier's handshake starts.
inline std::vector<std::uint8_t> hello(std::int32_t specifier, const std::string& sender) {
  std::vector<std::uint8_t> out;
  auto h = carrier::make_yarp_number(specifier);
  out.insert(out.end(), h.begin(), h.end());
  std::uint8_t len[4];
  carrier::put_int32(len, static_cast<std::int32_t>(sender.size() + 1));
  out.insert(out.end(), len, len + 4);
  out.insert(out.end(), sender.begin(), sender.end());
  out.push_back(0);
  return out;
}

inline net::TcpStream connect_to(const Port& p) {
  return net::TcpStream::connect({"127.0.0.1", p.contact().port});
}

// A well-behaved writer connects, sends a Bottle and it is read: the port still serves.
inline bool legit_client_served(Port& r, const std::string& writer = "/legit") {
  Port w;
  w.open_at(writer, {"127.0.0.1", 0});
  try {
    w.add_output(Contact{r.name(), "tcp", "127.0.0.1", r.contact().port});
  } catch (const std::exception&) {
    return false;
  }
  std::thread t([&] { w.write(Bottle{Value("alive")}); });
  Bottle b;
  bool got = r.read(b, false, std::chrono::milliseconds(5000));
  t.join();
  return got && b.to_text() == "alive";
}

}  // namespace robogene::test
