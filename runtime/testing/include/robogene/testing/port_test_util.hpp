// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Ports on 127.0.0.1 with ephemeral numbers, found through a table instead of a name server.
#pragma once

#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "robogene/testing/wire_helpers.hpp"
#include "robogene/port.hpp"

namespace robogene::test {

class PortTable {
 public:
  void add(const Port& p) {
    std::lock_guard<std::mutex> lock(mutex_);
    table_[p.name()] = p.contact();
  }
  Port::Resolver resolver() {
    return [this](const std::string& n) -> std::optional<Contact> {
      std::lock_guard<std::mutex> lock(mutex_);
      auto it = table_.find(n);
      if (it == table_.end()) return std::nullopt;
      return it->second;
    };
  }

 private:
  std::mutex mutex_;
  std::map<std::string, Contact> table_;
};

inline void open_local(Port& p, const std::string& name, PortTable& table) {
  p.open_at(name, {"127.0.0.1", 0});
  p.set_resolver(table.resolver());
  table.add(p);
}

// One text_ack admin exchange on a fresh connection, as `yarp connect` does it: the reply with
// its "\r\n<ACK>\r\n" ending.
inline std::string admin_text(const Port& p, const std::string& request) {
  auto s = net::TcpStream::connect({"127.0.0.1", p.contact().port});
  send(s, std::string("CONNACK admin\r\n"));
  if (read_until(s, "\r\n") != "Welcome admin\r\n") return "(no welcome)";
  send(s, "a\r\n" + request + "\r\n");
  return read_until(s, "<ACK>\r\n");
}

// Polls `condition` every 10 ms for up to 5 s; whether it became true.
template <typename Condition>
bool wait_until(Condition condition) {
  for (int i = 0; i < 500; ++i) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return condition();
}

}  // namespace robogene::test
