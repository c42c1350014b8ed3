// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Minimal logging for the runtime. The level comes from $ROBOGENE_LOG (debug, info, warn, error,
// off; default warn); lines go to stderr as "[WARN] /port: text" so they name the port and,
// where relevant, the peer.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace robogene::log {

enum class Level { Debug = 0, Info = 1, Warn = 2, Error = 3, Off = 4 };

Level level() noexcept;
void set_level(Level l) noexcept;  // overrides the environment (tests)
bool enabled(Level l) noexcept;
// Writes one line if `l` is enabled. `who` is a port name or a component ("name-client").
void write(Level l, std::string_view who, std::string_view text);

// Where lines go instead of stderr (tests that check what was logged; an embedding program's
// own logger); an empty function restores stderr. Called under the log's lock, one line a call.
using Sink = std::function<void(Level, std::string_view who, std::string_view text)>;
void set_sink(Sink sink);

inline void debug(std::string_view who, const std::string& t) {
  if (enabled(Level::Debug)) write(Level::Debug, who, t);
}
inline void info(std::string_view who, const std::string& t) {
  if (enabled(Level::Info)) write(Level::Info, who, t);
}
inline void warn(std::string_view who, const std::string& t) {
  if (enabled(Level::Warn)) write(Level::Warn, who, t);
}
inline void error(std::string_view who, const std::string& t) {
  if (enabled(Level::Error)) write(Level::Error, who, t);
}

}  // namespace robogene::log
