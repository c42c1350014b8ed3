// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// What every `robogene` command shares: argument handling, finding the name server (--server or
// yarp.conf), error reporting and clean shutdown on SIGINT / SIGTERM.
#pragma once

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "robogene/net/endpoint.hpp"

namespace robogene::cli {

// A mistake in the command line: reported with the command's usage, exit status 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The words after the command name, with options taken out as they are asked for.
class Args {
 public:
  explicit Args(std::vector<std::string> words) : words_(std::move(words)) {}
  // Removes "--name VALUE" or "--name=VALUE"; UsageError when VALUE is missing.
  std::optional<std::string> option(const std::string& name);
  // Removes a "--name" switch; true when it was there.
  bool flag(const std::string& name);
  // The remaining words (call after every option/flag was taken). UsageError on a leftover "--x".
  std::vector<std::string> positional() const;
  // Every remaining word, options included (for commands that take free-form --key value).
  const std::vector<std::string>& rest() const { return words_; }

 private:
  std::vector<std::string> words_;
};

// "HOST:PORT" -> Endpoint; UsageError naming `what` and the text when malformed.
net::Endpoint parse_host_port(const std::string& text, const std::string& what);
// A whole number in [lo, hi]; UsageError naming `what` otherwise.
long parse_number(const std::string& text, const std::string& what, long lo, long hi);
double parse_seconds(const std::string& text, const std::string& what);
// A size in bytes, optionally with a k, M or G suffix (powers of 1024), at least 1 and at most
// 2 GiB; UsageError naming `what` otherwise.
std::size_t parse_bytes(const std::string& text, const std::string& what);

// Where the name server is: --server if given, else yarp.conf, else 127.0.0.1:10000.
net::Endpoint name_server_address(Args& args);

// YARP's configuration directory ($YARP_CONFIG_HOME, $XDG_CONFIG_HOME/yarp, ~/.config/yarp).
std::string config_dir();

// Blocks SIGINT and SIGTERM in every thread (call first in main), so that they are taken only
// where we wait for them.
void block_shutdown_signals();
// Returns when SIGINT or SIGTERM arrives (the caller then shuts down in its own thread).
void wait_for_shutdown_signal();
// For commands whose main thread is blocked reading stdin: runs `handler` on a watcher thread
// when a signal arrives. The handler must end the process (it runs while main is still busy).
void on_shutdown_signal(std::function<void()> handler);

}  // namespace robogene::cli
