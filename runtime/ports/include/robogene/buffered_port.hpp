// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// BufferedPort: a Port with a receive buffer, so input threads never wait for the user.
// Latest-only keeps just the newest message (a reader that falls behind skips stale data, the
// usual choice for sensor streams); strict keeps every message up to a bound. Writing goes
// through prepare()/write() like YARP's BufferedPort<Bottle>.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>

#include "robogene/port.hpp"

namespace robogene {

enum class BufferPolicy { LatestOnly, Strict };

class BufferedPort {
 public:
  using Callback = std::function<void(const Bottle& b, const MessageInfo& info)>;

  explicit BufferedPort(BufferPolicy policy = BufferPolicy::LatestOnly,
                        std::size_t strict_capacity = 1000, PortOptions options = {});
  ~BufferedPort();

  Port& port() noexcept { return port_; }
  void open(const std::string& name) { port_.open(name); }
  void open(const std::string& name, NameClient names) { port_.open(name, std::move(names)); }
  void open_at(const std::string& name, const net::Endpoint& at) { port_.open_at(name, at); }
  void close();

  // The Bottle the next write() sends; cleared by each prepare().
  Bottle& prepare();
  // Sends the prepared Bottle to every output; false when there is no output.
  bool write();

  // Blocking read: waits for a message (or the timeout / close, then nullopt).
  std::optional<Bottle> read(net::Millis timeout = net::kNoTimeout, MessageInfo* info = nullptr);
  // Non-blocking read: nullopt when nothing is waiting.
  std::optional<Bottle> poll(MessageInfo* info = nullptr);
  std::size_t pending() const;
  // Messages thrown away: replaced under LatestOnly, or over capacity under Strict.
  std::size_t dropped() const;

  // Called on the input thread for every message instead of buffering it.
  void set_callback(Callback cb);

 private:
  void on_message(const Bottle& b, const MessageInfo& info);

  BufferPolicy policy_;
  std::size_t capacity_;
  Port port_;
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  std::deque<std::pair<Bottle, MessageInfo>> queue_;
  std::size_t dropped_ = 0;
  bool closed_ = false;
  Callback callback_;
  Bottle prepared_;
};

}  // namespace robogene
