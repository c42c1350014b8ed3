// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name/registry.hpp"

#include <sqlite3.h>

#include <set>
#include <utility>

#include "robogene/error.hpp"

namespace robogene::name {
namespace {

// Bumped when the tables change incompatibly; an older server refuses a newer file.
constexpr int kSchemaVersion = 1;

const char* const kSchema = R"sql(
CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value INTEGER NOT NULL);
CREATE TABLE IF NOT EXISTS registrations (
  name TEXT PRIMARY KEY, carrier TEXT NOT NULL, host TEXT NOT NULL, port INTEGER NOT NULL,
  type TEXT NOT NULL, registered_at REAL NOT NULL);
CREATE TABLE IF NOT EXISTS properties (
  name TEXT NOT NULL, key TEXT NOT NULL, value TEXT NOT NULL);
CREATE INDEX IF NOT EXISTS properties_by_key ON properties (name, key, value);
CREATE TABLE IF NOT EXISTS preferred_ports (name TEXT PRIMARY KEY, port INTEGER NOT NULL);
)sql";

// One prepared statement; finalized on scope exit so that an exception never leaks it.
class Statement {
 public:
  Statement(sqlite3* db, const char* sql) : db_(db) {
    if (sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr) != SQLITE_OK) {
      throw Error(std::string("name server database: cannot prepare \"") + sql + "\": " + sqlite3_errmsg(db));
    }
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int i, const std::string& s) {
    sqlite3_bind_text(stmt_, i, s.data(), static_cast<int>(s.size()), SQLITE_TRANSIENT);
    return *this;
  }
  Statement& bind(int i, long long v) {
    sqlite3_bind_int64(stmt_, i, v);
    return *this;
  }
  Statement& bind_double(int i, double v) {
    sqlite3_bind_double(stmt_, i, v);
    return *this;
  }
  // True while a row is available.
  bool step() {
    int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    throw Error(std::string("name server database: ") + sqlite3_errmsg(db_));
  }
  std::string text(int col) const {
    const unsigned char* p = sqlite3_column_text(stmt_, col);
    return p ? std::string(reinterpret_cast<const char*>(p), static_cast<std::size_t>(sqlite3_column_bytes(stmt_, col)))
             : std::string();
  }
  long long integer(int col) const { return sqlite3_column_int64(stmt_, col); }
  double real(int col) const { return sqlite3_column_double(stmt_, col); }

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

Registration row_to_registration(const Statement& s) {
  Registration r;
  r.name = s.text(0);
  r.carrier = s.text(1);
  r.host = s.text(2);
  r.port = static_cast<int>(s.integer(3));
  r.type = s.text(4);
  r.registered_at = s.real(5);
  return r;
}

// Groups statements into one transaction; rolled back unless commit() is reached.
class Transaction {
 public:
  explicit Transaction(sqlite3* db) : db_(db) { sqlite3_exec(db_, "BEGIN IMMEDIATE", nullptr, nullptr, nullptr); }
  ~Transaction() {
    if (!done_) sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
  }
  void commit() {
    if (sqlite3_exec(db_, "COMMIT", nullptr, nullptr, nullptr) != SQLITE_OK) {
      throw Error(std::string("name server database: commit failed: ") + sqlite3_errmsg(db_));
    }
    done_ = true;
  }

 private:
  sqlite3* db_;
  bool done_ = false;
};

}  // namespace

Registry::Registry(const std::string& path) : path_(path) {
  int rc = sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                           nullptr);
  if (rc != SQLITE_OK) fail("cannot open");
  sqlite3_busy_timeout(db_, 2000);
  // Committed registrations must survive the process being killed; WAL keeps writes cheap.
  if (path != ":memory:") exec("PRAGMA journal_mode=WAL");
  exec("PRAGMA synchronous=NORMAL");
  exec(kSchema);
  Statement read(db_, "SELECT value FROM meta WHERE key = 'schema'");
  if (read.step()) {
    long long version = read.integer(0);
    if (version > kSchemaVersion) {
      sqlite3_close(db_);
      db_ = nullptr;
      throw Error("name server database " + path + ": schema version " + std::to_string(version) +
                  " is newer than this server understands (" + std::to_string(kSchemaVersion) + ")");
    }
  } else {
    Statement(db_, "INSERT INTO meta (key, value) VALUES ('schema', ?1)").bind(1, kSchemaVersion).step();
  }
}

Registry::~Registry() {
  if (db_) sqlite3_close(db_);
}

void Registry::fail(const std::string& doing) {
  std::string msg = "name server database " + path_ + ": " + doing + ": " +
                    (db_ ? sqlite3_errmsg(db_) : "out of memory");
  if (db_) sqlite3_close(db_);
  db_ = nullptr;
  throw Error(msg);
}

void Registry::exec(const char* sql) {
  char* err = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &err) != SQLITE_OK) {
    std::string msg = err ? err : "unknown error";
    sqlite3_free(err);
    sqlite3_close(db_);
    db_ = nullptr;
    throw Error("name server database " + path_ + ": " + msg);
  }
}

std::optional<Registration> Registry::find(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  Statement s(db_, "SELECT name, carrier, host, port, type, registered_at FROM registrations WHERE name = ?1");
  s.bind(1, name);
  if (!s.step()) return std::nullopt;
  return row_to_registration(s);
}

std::vector<Registration> Registry::list() {
  std::lock_guard<std::mutex> lock(mutex_);
  Statement s(db_, "SELECT name, carrier, host, port, type, registered_at FROM registrations ORDER BY name");
  std::vector<Registration> out;
  while (s.step()) out.push_back(row_to_registration(s));
  return out;
}

void Registry::put(const Registration& r) {
  std::lock_guard<std::mutex> lock(mutex_);
  Transaction tx(db_);
  Statement(db_, "DELETE FROM properties WHERE name = ?1").bind(1, r.name).step();
  Statement(db_,
            "INSERT OR REPLACE INTO registrations (name, carrier, host, port, type, registered_at) "
            "VALUES (?1, ?2, ?3, ?4, ?5, ?6)")
      .bind(1, r.name)
      .bind(2, r.carrier)
      .bind(3, r.host)
      .bind(4, static_cast<long long>(r.port))
      .bind(5, r.type)
      .bind_double(6, r.registered_at)
      .step();
  if (r.carrier != "mcast") {
    Statement(db_, "INSERT OR REPLACE INTO preferred_ports (name, port) VALUES (?1, ?2)")
        .bind(1, r.name)
        .bind(2, static_cast<long long>(r.port))
        .step();
  }
  tx.commit();
}

bool Registry::remove(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  Transaction tx(db_);
  Statement(db_, "DELETE FROM properties WHERE name = ?1").bind(1, name).step();
  Statement(db_, "DELETE FROM registrations WHERE name = ?1").bind(1, name).step();
  bool existed = sqlite3_changes(db_) > 0;
  tx.commit();
  return existed;
}

bool Registry::remove_if_unchanged(const Registration& r) {
  std::lock_guard<std::mutex> lock(mutex_);
  Transaction tx(db_);
  Statement s(db_, "SELECT name, carrier, host, port, type, registered_at FROM registrations WHERE name = ?1");
  s.bind(1, r.name);
  if (!s.step()) return false;
  Registration now = row_to_registration(s);
  if (!(now == r) || now.registered_at != r.registered_at) return false;
  Statement(db_, "DELETE FROM properties WHERE name = ?1").bind(1, r.name).step();
  Statement(db_, "DELETE FROM registrations WHERE name = ?1").bind(1, r.name).step();
  tx.commit();
  return true;
}

bool Registry::set_property(const std::string& name, const std::string& key, const std::vector<std::string>& values) {
  std::lock_guard<std::mutex> lock(mutex_);
  Transaction tx(db_);
  Statement exists(db_, "SELECT 1 FROM registrations WHERE name = ?1");
  exists.bind(1, name);
  if (!exists.step()) return false;
  Statement(db_, "DELETE FROM properties WHERE name = ?1 AND key = ?2").bind(1, name).bind(2, key).step();
  for (const auto& v : values) {
    Statement(db_, "INSERT INTO properties (name, key, value) VALUES (?1, ?2, ?3)")
        .bind(1, name)
        .bind(2, key)
        .bind(3, v)
        .step();
  }
  tx.commit();
  return true;
}

std::vector<std::string> Registry::get_property(const std::string& name, const std::string& key) {
  std::lock_guard<std::mutex> lock(mutex_);
  Statement s(db_, "SELECT value FROM properties WHERE name = ?1 AND key = ?2 ORDER BY value, rowid");
  s.bind(1, name).bind(2, key);
  std::vector<std::string> out;
  while (s.step()) out.push_back(s.text(0));
  return out;
}

std::vector<std::string> Registry::names_with_property(const std::string& key, const std::string& value) {
  std::lock_guard<std::mutex> lock(mutex_);
  Statement s(db_, "SELECT DISTINCT name FROM properties WHERE key = ?1 AND value = ?2 ORDER BY name");
  s.bind(1, key).bind(2, value);
  std::vector<std::string> out;
  while (s.step()) out.push_back(s.text(0));
  return out;
}

long long Registry::counter(const char* key, long long initial) {
  Statement s(db_, "SELECT value FROM meta WHERE key = ?1");
  s.bind(1, std::string(key));
  return s.step() ? s.integer(0) : initial;
}

void Registry::set_counter(const char* key, long long value) {
  Statement(db_, "INSERT OR REPLACE INTO meta (key, value) VALUES (?1, ?2)").bind(1, std::string(key)).bind(2, value).step();
}

int Registry::allocate_port(const std::string& name, int lo, int hi, const std::function<bool(int)>& usable) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (lo > hi) throw Error("name server: empty port range " + std::to_string(lo) + ".." + std::to_string(hi));
  std::set<long long> held;
  {
    Statement s(db_, "SELECT port FROM registrations WHERE carrier != 'mcast'");
    while (s.step()) held.insert(s.integer(0));
  }
  {
    Statement s(db_, "SELECT port FROM preferred_ports WHERE name = ?1");
    s.bind(1, name);
    if (s.step()) {
      long long p = s.integer(0);
      if (p >= lo && p <= hi && !held.count(p) && (!usable || usable(static_cast<int>(p)))) {
        return static_cast<int>(p);
      }
    }
  }
  long long last = counter("last_port", lo - 1);
  long long span = static_cast<long long>(hi) - lo + 1;
  for (long long i = 1; i <= span; ++i) {
    long long candidate = lo + ((last - lo + i) % span + span) % span;
    if (!held.count(candidate) && (!usable || usable(static_cast<int>(candidate)))) {
      set_counter("last_port", candidate);
      return static_cast<int>(candidate);
    }
  }
  throw Error("name server: every port number in " + std::to_string(lo) + ".." + std::to_string(hi) +
              " is registered; unregister stale ports first");
}

std::string Registry::allocate_name() {
  std::lock_guard<std::mutex> lock(mutex_);
  long long id = counter("tmp_id", 0);
  for (;;) {
    ++id;
    std::string name = "/tmp/port/" + std::to_string(id);
    Statement s(db_, "SELECT 1 FROM registrations WHERE name = ?1");
    s.bind(1, name);
    if (!s.step()) {
      set_counter("tmp_id", id);
      return name;
    }
  }
}

std::string Registry::allocate_mcast_host() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::set<std::string> held;
  {
    Statement s(db_, "SELECT host FROM registrations WHERE carrier = 'mcast'");
    while (s.step()) held.insert(s.text(0));
  }
  // 224.1.1.1 .. 224.1.255.255 as yarpserver hands them out (cursor / 255, cursor % 255).
  const long long span = 255LL * 255LL;
  long long cursor = counter("mcast_cursor", 0);
  for (long long i = 1; i <= span; ++i) {
    long long c = (cursor + i) % span;
    std::string host = "224.1." + std::to_string(c / 255 + 1) + "." + std::to_string(c % 255 + 1);
    if (!held.count(host)) {
      set_counter("mcast_cursor", c);
      return host;
    }
  }
  throw Error("name server: every multicast group 224.1.x.y is registered");
}

}  // namespace robogene::name
