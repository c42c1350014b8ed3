// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/log.hpp"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <utility>

namespace robogene::log {

namespace {

Level from_env() {
  const char* v = std::getenv("ROBOGENE_LOG");
  if (!v) return Level::Warn;
  if (!std::strcmp(v, "debug")) return Level::Debug;
  if (!std::strcmp(v, "info")) return Level::Info;
  if (!std::strcmp(v, "warn")) return Level::Warn;
  if (!std::strcmp(v, "error")) return Level::Error;
  if (!std::strcmp(v, "off")) return Level::Off;
  return Level::Warn;
}

std::atomic<int>& current() {
  static std::atomic<int> l{static_cast<int>(from_env())};
  return l;
}

const char* tag(Level l) {
  switch (l) {
    case Level::Debug: return "DEBUG";
    case Level::Info: return "INFO";
    case Level::Warn: return "WARN";
    case Level::Error: return "ERROR";
    default: return "";
  }
}

std::mutex& write_mutex() {
  static std::mutex m;
  return m;
}

Sink& sink() {
  static Sink s;
  return s;
}

}  // namespace

Level level() noexcept { return static_cast<Level>(current().load()); }
void set_level(Level l) noexcept { current().store(static_cast<int>(l)); }
bool enabled(Level l) noexcept { return static_cast<int>(l) >= current().load(); }

void set_sink(Sink s) {
  std::lock_guard<std::mutex> lock(write_mutex());
  sink() = std::move(s);
}

void write(Level l, std::string_view who, std::string_view text) {
  std::lock_guard<std::mutex> lock(write_mutex());
  if (sink()) {
    sink()(l, who, text);
    return;
  }
  std::fprintf(stderr, "[%s] %.*s: %.*s\n", tag(l), static_cast<int>(who.size()), who.data(),
               static_cast<int>(text.size()), text.data());
}

}  // namespace robogene::log
