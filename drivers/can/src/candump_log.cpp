// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/candump_log.hpp"

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>

#include "robogene/error.hpp"

namespace robogene::can {
namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Seconds since the epoch (about the year 5138): beyond, microseconds overflow a long long.
constexpr double kMaxTimestamp = 1e11;

// A cursor over one line; columns are 1-based in messages.
struct Cursor {
  const std::string& s;
  std::size_t i = 0;
  [[noreturn]] void fail(const std::string& expected) const {
    throw ParseError(i + 1, "column " + std::to_string(i + 1) + ": expected " + expected +
                                (i < s.size() ? std::string(", found '") + s[i] + "'" : ", found end of line"));
  }
  void expect(char c, const char* what) {
    if (i >= s.size() || s[i] != c) fail(what);
    ++i;
  }
};

}  // namespace

double wall_time() {
  using namespace std::chrono;
  return duration<double>(system_clock::now().time_since_epoch()).count();
}

std::string format_log_line(const LogEntry& e) {
  // Whole microseconds, split as candump does (seconds padded to 10 digits).
  const auto micros = static_cast<long long>(std::llround(e.time * 1e6));
  char head[64];
  std::snprintf(head, sizeof head, "(%010lld.%06lld) ", micros / 1000000, micros % 1000000);
  std::string line = head + e.interface + " ";
  if (e.error) {
    char id[16];
    std::snprintf(id, sizeof id, "%08X#", e.error->can_id | kErrFlag);
    line += id;
    for (std::uint8_t b : e.error->data) {
      char h[3];
      std::snprintf(h, sizeof h, "%02X", b);
      line += h;
    }
  } else if (e.frame) {
    line += to_string(*e.frame);
  }
  return line;
}

LogEntry parse_log_line(const std::string& line) {
  Cursor c{line};
  LogEntry e;
  c.expect('(', "'(' opening the timestamp");
  const std::size_t ts_start = c.i;
  while (c.i < line.size() && (std::isdigit(static_cast<unsigned char>(line[c.i])) || line[c.i] == '.')) ++c.i;
  if (c.i == ts_start) c.fail("a timestamp (seconds.microseconds)");
  // The whole token must be one number, small enough that its microseconds fit the writer's
  // integer: "(70001700000000.5)" used to read, then print back as garbage (can_frame_fuzz).
  const std::string stamp = line.substr(ts_start, c.i - ts_start);
  char* stamp_end = nullptr;
  e.time = std::strtod(stamp.c_str(), &stamp_end);
  if (stamp_end != stamp.c_str() + stamp.size() || !(e.time < kMaxTimestamp)) {
    c.i = ts_start;
    c.fail("a timestamp (seconds.microseconds) below " + std::to_string(static_cast<long long>(kMaxTimestamp)));
  }
  c.expect(')', "')' closing the timestamp");
  c.expect(' ', "a space before the interface name");
  const std::size_t if_start = c.i;
  while (c.i < line.size() && line[c.i] != ' ') ++c.i;
  if (c.i == if_start) c.fail("an interface name");
  e.interface = line.substr(if_start, c.i - if_start);
  c.expect(' ', "a space before the frame");
  const std::size_t id_start = c.i;
  std::uint32_t id = 0;
  while (c.i < line.size() && hex_digit(line[c.i]) >= 0) {
    id = (id << 4) | static_cast<std::uint32_t>(hex_digit(line[c.i]));
    ++c.i;
  }
  const std::size_t digits = c.i - id_start;
  if (digits != 3 && digits != 8) {
    c.i = id_start;
    c.fail("a 3-digit standard id or an 8-digit extended/error id");
  }
  c.expect('#', "'#' after the id");
  if (c.i < line.size() && (line[c.i] == 'R' || line[c.i] == '#')) c.fail("a classic data frame (RTR and CAN FD frames are not used)");
  std::vector<std::uint8_t> bytes;
  while (c.i < line.size() && !std::isspace(static_cast<unsigned char>(line[c.i]))) {
    if (bytes.size() == kMaxDataLength) c.fail("at most 8 data bytes");
    if (c.i + 1 >= line.size() || hex_digit(line[c.i]) < 0 || hex_digit(line[c.i + 1]) < 0) {
      c.fail("two hex digits per data byte");
    }
    bytes.push_back(static_cast<std::uint8_t>(hex_digit(line[c.i]) * 16 + hex_digit(line[c.i + 1])));
    c.i += 2;
  }
  if (digits == 8) {
    if (!(id & kErrFlag)) {
      c.i = id_start;
      c.fail("a standard id: extended frames are not used on this bus");
    }
    ErrorFrame err;
    err.can_id = id;
    std::copy(bytes.begin(), bytes.end(), err.data.begin());
    e.error = err;
  } else {
    if (id > kMaxStandardId) {
      c.i = id_start;
      c.fail("an id no larger than 7FF");
    }
    e.frame = Frame(static_cast<std::uint16_t>(id), bytes);
  }
  return e;
}

std::vector<LogEntry> read_candump_log(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot open candump log: " + std::strerror(errno));
  std::vector<LogEntry> out;
  std::string line;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    try {
      out.push_back(parse_log_line(line));
    } catch (const ParseError& e) {
      throw Error(path + ":" + std::to_string(n) + ":" + std::to_string(e.position()) + ": " +
                  std::string(e.what()).substr(std::string(e.what()).find(':') + 2));
    }
  }
  return out;
}

CandumpWriter::CandumpWriter(const std::string& path) : path_(path) {
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) throw Error(path + ": cannot create candump log: " + std::strerror(errno));
}

CandumpWriter::~CandumpWriter() {
  if (file_) std::fclose(file_);
}

void CandumpWriter::write(const LogEntry& e) {
  const std::string line = format_log_line(e) + "\n";
  std::lock_guard<std::mutex> lock(mutex_);
  std::fputs(line.c_str(), file_);
  std::fflush(file_);
}

void CandumpWriter::write(const std::string& interface, const Frame& f) {
  LogEntry e;
  e.time = wall_time();
  e.interface = interface;
  e.frame = f;
  write(e);
}

void CandumpWriter::write(const std::string& interface, const ErrorFrame& err) {
  LogEntry e;
  e.time = wall_time();
  e.interface = interface;
  e.error = err;
  write(e);
}

}  // namespace robogene::can
