// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Virtual backend: a CAN bus between processes of one machine, for tests and simulation where
// the kernel has no CAN. Bus "NAME" is a directory ($ROBOGENE_CAN_DIR, else
// /tmp/robogene-can-<uid>, then NAME); each node binds a Unix datagram socket in it and sends
// every frame to every other node's socket, so every node sees every other node's frames and
// never its own, as on SocketCAN. Error frames travel the same way, so a test can make a bus
// report bus-off or error-passive to every node (inject_error).
//
// A node whose receive queue stays full for kCongestionWait loses that frame (and the loss is
// logged), as a real controller's receive FIFO overflows; it never stalls the other nodes.
#pragma once

#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "robogene/can/bus.hpp"

namespace robogene::can {

class VirtualBus final : public Bus {
 public:
  static constexpr Millis kCongestionWait{20};

  // Throws robogene::Error when `bus_name` is not [A-Za-z0-9_.-]+ or the directory path is too
  // long for a socket address, BusError(io) when the directory or socket cannot be made.
  explicit VirtualBus(const std::string& bus_name);
  ~VirtualBus() override;
  VirtualBus(const VirtualBus&) = delete;
  VirtualBus& operator=(const VirtualBus&) = delete;

  static std::string directory_for(const std::string& bus_name);

  void send(const Frame& frame, Millis timeout) override;
  std::optional<Frame> receive(Millis timeout) override;
  void set_filters(const std::vector<Filter>& filters) override;
  std::string name() const override { return "virtual:" + bus_name_; }
  std::string interface() const override { return bus_name_; }

  // Puts an error frame on the bus: every other node's receive() throws the BusError it decodes to.
  void inject_error(const ErrorFrame& e);
  // Frames this node dropped because a peer's queue stayed full.
  std::uint64_t dropped() const;

 private:
  struct Peer {
    int fd = -1;
    std::chrono::steady_clock::time_point congested_until{};
  };
  void broadcast(const std::uint8_t* datagram, std::size_t size, Millis timeout, const std::string& what);
  void refresh_peers();  // with mutex_ held
  void forget(const std::string& path, bool stale);

  std::string bus_name_;
  std::string dir_;
  std::string own_path_;
  int fd_ = -1;
  mutable std::mutex mutex_;
  std::map<std::string, Peer> peers_;
  std::int64_t listed_mtime_ns_ = -1;
  mutable std::mutex filters_mutex_;  // apart from mutex_, so a send waiting on a peer never blocks receive
  std::vector<Filter> filters_;
  std::uint64_t dropped_ = 0;
};

}  // namespace robogene::can
