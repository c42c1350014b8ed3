// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// candump's log format (`candump -l`, read by canplayer, cantools and python-can):
//   (1700000000.123456) vcan0 123#DEADBEEF
// Standard frames have a 3-digit id; error frames an 8-digit one with CAN_ERR_FLAG
// (20000040#... for bus-off), as candump writes them.
#pragma once

#include <cstdio>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "robogene/can/bus_error.hpp"
#include "robogene/can/frame.hpp"

namespace robogene::can {

struct LogEntry {
  double time = 0.0;  // seconds since the epoch
  std::string interface;
  std::optional<Frame> frame;        // a data frame...
  std::optional<ErrorFrame> error;   // ...or an error frame
};

// One line, without the newline.
std::string format_log_line(const LogEntry& e);
// Parses one line. Throws ParseError (column = position) naming what was expected.
LogEntry parse_log_line(const std::string& line);

// Reads a whole log. Throws robogene::Error "FILE:LINE:COLUMN: ..." on the first bad line.
std::vector<LogEntry> read_candump_log(const std::string& path);

// Appends lines to a log file; safe to use from several threads. Each line is flushed, so a log
// is complete up to the last frame even when the program is killed.
class CandumpWriter {
 public:
  // Throws robogene::Error naming the path when it cannot be opened.
  explicit CandumpWriter(const std::string& path);
  ~CandumpWriter();
  CandumpWriter(const CandumpWriter&) = delete;
  CandumpWriter& operator=(const CandumpWriter&) = delete;

  void write(const LogEntry& e);
  // Stamps with the wall clock, as candump does.
  void write(const std::string& interface, const Frame& f);
  void write(const std::string& interface, const ErrorFrame& e);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  std::mutex mutex_;
};

double wall_time();

}  // namespace robogene::can
