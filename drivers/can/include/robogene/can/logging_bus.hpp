// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// LoggingBus: a Bus that writes every frame this node sends or receives, and every error frame
// it is told of, to a candump log, and otherwise behaves exactly as the bus it wraps.
#pragma once

#include <memory>

#include "robogene/can/bus.hpp"
#include "robogene/can/candump_log.hpp"

namespace robogene::can {

class LoggingBus final : public Bus {
 public:
  LoggingBus(std::unique_ptr<Bus> inner, std::shared_ptr<CandumpWriter> log)
      : inner_(std::move(inner)), log_(std::move(log)) {}

  void send(const Frame& frame, Millis timeout) override {
    inner_->send(frame, timeout);
    log_->write(inner_->interface(), frame);
  }
  std::optional<Frame> receive(Millis timeout) override {
    try {
      auto f = inner_->receive(timeout);
      if (f) log_->write(inner_->interface(), *f);
      return f;
    } catch (const BusError& e) {
      if (e.frame()) log_->write(inner_->interface(), *e.frame());
      throw;
    }
  }
  void set_filters(const std::vector<Filter>& filters) override { inner_->set_filters(filters); }
  std::string name() const override { return inner_->name(); }
  std::string interface() const override { return inner_->interface(); }
  Bus& inner() { return *inner_; }

 private:
  std::unique_ptr<Bus> inner_;
  std::shared_ptr<CandumpWriter> log_;
};

}  // namespace robogene::can
