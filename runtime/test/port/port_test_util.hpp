// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Ports on 127.0.0.1 with ephemeral numbers, found through a table instead of a name server.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>

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

}  // namespace robogene::test
