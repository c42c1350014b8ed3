// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The name server's memory: registrations, their properties and the allocator's counters, kept in
// an SQLite database so that a restarted server still knows every port. One Registry per database
// file; every method is safe to call from several threads.
#pragma once

#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "robogene/name/registration.hpp"

struct sqlite3;

namespace robogene::name {

class Registry {
 public:
  // Opens (creating if needed) the database at `path`; ":memory:" keeps it in memory. Throws
  // robogene::Error naming the file and what SQLite reported (unreadable, not a database, a
  // newer schema...).
  explicit Registry(const std::string& path);
  ~Registry();
  Registry(const Registry&) = delete;
  Registry& operator=(const Registry&) = delete;

  const std::string& path() const noexcept { return path_; }

  std::optional<Registration> find(const std::string& name);
  std::vector<Registration> list();  // ordered by name

  // Stores `r`, replacing any entry of the same name together with its properties.
  void put(const Registration& r);
  // Drops the entry and its properties; false when there was none.
  bool remove(const std::string& name);
  // Drops the entry only if it is still exactly `r` (a stale check must not remove a port that
  // re-registered while it was being probed).
  bool remove_if_unchanged(const Registration& r);

  // Properties are multi-valued; values come back sorted (as yarpserver's index returns them).
  // set_property returns false when the port is not registered.
  bool set_property(const std::string& name, const std::string& key, const std::vector<std::string>& values);
  std::vector<std::string> get_property(const std::string& name, const std::string& key);
  // Ports having `key` = `value` among their properties, ordered by name.
  std::vector<std::string> names_with_property(const std::string& key, const std::string& value);

  // Port number for `name` in [lo, hi]: the number it had last time if no registration holds it
  // now, else the next free one after the last number handed out (wrapping). Throws
  // robogene::Error when every number in the range is held. `usable`, when given, can veto a
  // number (e.g. one some other program on this machine is using).
  int allocate_port(const std::string& name, int lo, int hi, const std::function<bool(int)>& usable = {});
  // A fresh name "/tmp/port/N" not held by any registration.
  std::string allocate_name();
  // A multicast group "224.1.x.y" not held by any mcast registration.
  std::string allocate_mcast_host();

 private:
  void exec(const char* sql);
  long long counter(const char* key, long long initial);
  void set_counter(const char* key, long long value);
  [[noreturn]] void fail(const std::string& doing);

  std::string path_;
  sqlite3* db_ = nullptr;
  std::mutex mutex_;
};

}  // namespace robogene::name
