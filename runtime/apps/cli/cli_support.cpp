// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "cli_support.hpp"

#include <pthread.h>
#include <signal.h>

#include <cerrno>
#include <cstdlib>
#include <thread>

#include "robogene/error.hpp"
#include "robogene/name_config.hpp"

namespace robogene::cli {

std::optional<std::string> Args::option(const std::string& name) {
  for (std::size_t i = 0; i < words_.size(); ++i) {
    const std::string& w = words_[i];
    if (w == name) {
      if (i + 1 >= words_.size()) throw UsageError(name + " needs a value");
      std::string value = words_[i + 1];
      words_.erase(words_.begin() + static_cast<long>(i), words_.begin() + static_cast<long>(i) + 2);
      return value;
    }
    if (w.compare(0, name.size() + 1, name + "=") == 0) {
      std::string value = w.substr(name.size() + 1);
      words_.erase(words_.begin() + static_cast<long>(i));
      return value;
    }
  }
  return std::nullopt;
}

bool Args::flag(const std::string& name) {
  for (std::size_t i = 0; i < words_.size(); ++i) {
    if (words_[i] == name) {
      words_.erase(words_.begin() + static_cast<long>(i));
      return true;
    }
  }
  return false;
}

std::vector<std::string> Args::positional() const {
  for (const auto& w : words_) {
    if (w.size() > 2 && w.compare(0, 2, "--") == 0) throw UsageError("unknown option " + w);
  }
  return words_;
}

long parse_number(const std::string& text, const std::string& what, long lo, long hi) {
  char* end = nullptr;
  errno = 0;
  long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno != 0 || v < lo || v > hi) {
    throw UsageError(what + " must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                     ", got \"" + text + "\"");
  }
  return v;
}

std::size_t parse_bytes(const std::string& text, const std::string& what) {
  std::string digits = text;
  unsigned long long unit = 1;
  if (!digits.empty()) {
    switch (digits.back()) {
      case 'k': case 'K': unit = 1ull << 10; break;
      case 'M': unit = 1ull << 20; break;
      case 'G': unit = 1ull << 30; break;
      default: break;
    }
    if (unit != 1) digits.pop_back();
  }
  char* end = nullptr;
  errno = 0;
  unsigned long long v = digits.empty() || digits[0] == '-' ? 0 : std::strtoull(digits.c_str(), &end, 10);
  if (digits.empty() || !end || *end != '\0' || errno != 0 || v == 0 || v > (2ull << 30) / unit) {
    throw UsageError(what + " must be a size in bytes from 1 to 2G (suffixes k, M, G), got \"" + text + "\"");
  }
  return static_cast<std::size_t>(v * unit);
}

double parse_seconds(const std::string& text, const std::string& what) {
  char* end = nullptr;
  double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(v >= 0) || v > 1e9) {
    throw UsageError(what + " must be a number of seconds (0 or more), got \"" + text + "\"");
  }
  return v;
}

net::Endpoint parse_host_port(const std::string& text, const std::string& what) {
  try {
    return NameConfig::parse_server(text);
  } catch (const Error& e) {
    throw UsageError(what + " expects HOST:PORT (for example 127.0.0.1:10000): " + e.what());
  }
}

net::Endpoint name_server_address(Args& args) {
  if (auto s = args.option("--server")) return parse_host_port(*s, "--server");
  return NameConfig::load().server;
}

std::string config_dir() { return NameConfig::config_dir(); }

void block_shutdown_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  // A reader that goes away must not kill us with SIGPIPE (stdout to a closed pipe).
  signal(SIGPIPE, SIG_IGN);
}

void wait_for_shutdown_signal() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  int sig = 0;
  while (sigwait(&set, &sig) != 0) {
  }
}

void on_shutdown_signal(std::function<void()> handler) {
  std::thread([handler = std::move(handler)] {
    wait_for_shutdown_signal();
    handler();
  }).detach();
}

}  // namespace robogene::cli
