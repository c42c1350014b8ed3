// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// BoardLink: the host's side of the bus for the robogene_can driver. It sends commands, waits
// for replies (one request at a time, matched by board, axis and command), and keeps what the
// boards broadcast (positions, speeds, modes, faults). A thread reads the bus; a bus-off or an
// I/O error the bus reports stays in force until the controller says it restarted, and every
// send and request fails with it meanwhile.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "motor_control.hpp"
#include "robogene/can/bus.hpp"

namespace robogene::can {

class BoardLink {
 public:
  using Clock = std::chrono::steady_clock;

  struct BoardState {
    std::optional<Clock::time_point> position_time, velocity_time, status_time;
    std::array<std::int32_t, 2> position{};
    std::array<double, 2> speed{}, acceleration{};  // count/s, count/s^2
    std::array<ControlMode, 2> mode{{ControlMode::idle, ControlMode::idle}};
    std::array<std::uint8_t, 2> faults{};
  };

  BoardLink(std::unique_ptr<Bus> bus, Millis reply_timeout);
  ~BoardLink();
  BoardLink(const BoardLink&) = delete;
  BoardLink& operator=(const BoardLink&) = delete;

  // Throws BusError (the fault in force, or the send's own) or CodecError (a value that does not fit).
  void send(int board, int axis, const Message& m);
  // Sends and waits for the board's reply, asking a second time after reply_timeout; throws
  // BusError(timeout) naming the board, axis and command when neither was answered.
  Envelope request(int board, int axis, const Message& m);

  BoardState state(int board) const;
  // The bus-off or I/O error in force, if any.
  std::optional<std::string> fault() const;
  // The last error the bus reported, whatever its kind ("" when none).
  std::string last_error() const;
  const std::string& bus_name() const { return bus_name_; }

 private:
  void read_loop();
  void take(const Envelope& e);

  std::unique_ptr<Bus> bus_;
  std::string bus_name_;
  Millis reply_timeout_;
  mutable std::mutex mutex_;
  std::condition_variable replied_;
  std::map<int, BoardState> boards_;
  std::optional<std::string> fault_;
  std::string last_error_;
  std::mutex request_mutex_;  // one request in flight
  struct Pending {
    int board, axis, code;
    std::optional<Envelope> reply;
  };
  std::optional<Pending> pending_;
  std::atomic<bool> running_{true};
  std::thread reader_;
};

}  // namespace robogene::can
