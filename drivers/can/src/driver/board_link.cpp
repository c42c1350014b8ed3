// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "board_link.hpp"

#include <type_traits>

#include "robogene/log.hpp"

namespace robogene::can {
namespace {

std::uint8_t code_of(const Message& m) {
  return std::visit([](const auto& x) { return std::decay_t<decltype(x)>::code; }, m);
}

}  // namespace

BoardLink::BoardLink(std::unique_ptr<Bus> bus, Millis reply_timeout)
    : bus_(std::move(bus)), bus_name_(bus_->name()), reply_timeout_(reply_timeout) {
  // Replies to the host (class 0, destination 0) and every broadcast (class 1).
  bus_->set_filters({{0x000, 0x70F}, {0x100, 0x700}});
  reader_ = std::thread([this] { read_loop(); });
}

BoardLink::~BoardLink() {
  running_ = false;
  if (reader_.joinable()) reader_.join();
}

void BoardLink::read_loop() {
  while (running_) {
    std::optional<Frame> f;
    try {
      f = bus_->receive(Millis(50));
    } catch (const BusError& e) {
      std::lock_guard<std::mutex> lock(mutex_);
      last_error_ = e.what();
      if (e.kind() == BusErrorKind::bus_off || e.kind() == BusErrorKind::io) {
        if (!fault_) log::error(bus_name_, e.what());
        fault_ = e.what();
        if (e.kind() == BusErrorKind::io) std::this_thread::sleep_for(Millis(50));  // do not spin on a dead socket
      } else if (e.kind() == BusErrorKind::restarted) {
        if (fault_) log::warn(bus_name_, "controller restarted; the bus is usable again");
        fault_.reset();
      } else {
        log::warn(bus_name_, e.what());
      }
      continue;
    }
    if (!f) continue;
    try {
      take(decode(*f));
    } catch (const CodecError& e) {
      log::warn(bus_name_, std::string("robogene_can ignores a frame: ") + e.what());
    }
  }
}

void BoardLink::take(const Envelope& e) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto now = Clock::now();
  BoardState& s = boards_[e.source];
  if (const auto* p = std::get_if<PositionBroadcast>(&e.message)) {
    s.position = {p->position0, p->position1};
    s.position_time = now;
  } else if (const auto* v = std::get_if<VelocityBroadcast>(&e.message)) {
    s.speed = {v->speed0, v->speed1};
    s.acceleration = {v->acceleration0, v->acceleration1};
    s.velocity_time = now;
  } else if (const auto* st = std::get_if<StatusBroadcast>(&e.message)) {
    s.mode = {st->mode0, st->mode1};
    if ((st->faults0 | st->faults1) && (st->faults0 != s.faults[0] || st->faults1 != s.faults[1])) {
      std::string named;
      for (int axis = 0; axis < 2; ++axis) {
        const std::uint8_t f = axis == 0 ? st->faults0 : st->faults1;
        if (f) named += " axis " + std::to_string(axis) + ": " + axis_faults::names(f) + ";";
      }
      log::error(bus_name_, "board " + std::to_string(e.source) + " reports faults:" + named + " " + to_text(e));
    }
    s.faults = {st->faults0, st->faults1};
    s.status_time = now;
  } else if (message_kind(e.message) == MessageKind::reply && pending_ && pending_->board == e.source &&
             pending_->axis == e.axis && pending_->code == code_of(e.message)) {
    pending_->reply = e;
    replied_.notify_all();
  }
}

void BoardLink::send(int board, int axis, const Message& m) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (fault_) throw BusError(BusErrorKind::bus_off, "cannot send " + std::string(message_name(m)) + ": " + *fault_);
  }
  const Frame f = encode(Envelope{kHostAddress, static_cast<std::uint8_t>(board), static_cast<std::uint8_t>(axis), m});
  bus_->send(f, reply_timeout_);
}

Envelope BoardLink::request(int board, int axis, const Message& m) {
  std::lock_guard<std::mutex> one(request_mutex_);
  // Asked twice before giving up: requests only read, and one lost frame should not fail a call.
  for (int attempt = 1; attempt <= 2; ++attempt) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      pending_ = Pending{board, axis, code_of(m), std::nullopt};
    }
    try {
      send(board, axis, m);
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      pending_.reset();
      throw;
    }
    std::unique_lock<std::mutex> lock(mutex_);
    replied_.wait_for(lock, reply_timeout_, [&] { return pending_->reply.has_value() || fault_.has_value(); });
    std::optional<Envelope> reply = pending_->reply;
    pending_.reset();
    if (reply) return *reply;
    if (fault_) throw BusError(BusErrorKind::bus_off, std::string(message_name(m)) + " to board " + std::to_string(board) + ": " + *fault_);
    if (attempt == 1) log::warn(bus_name_, "board " + std::to_string(board) + " did not answer " + message_name(m) + "; asking again");
  }
  throw BusError(BusErrorKind::timeout, bus_name_ + ": board " + std::to_string(board) + " axis " + std::to_string(axis) +
                                            " did not answer " + message_name(m) + " within " +
                                            std::to_string(reply_timeout_.count()) + " ms (asked twice)");
}

BoardLink::BoardState BoardLink::state(int board) const {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = boards_.find(board);
  return it == boards_.end() ? BoardState{} : it->second;
}

std::optional<std::string> BoardLink::fault() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return fault_;
}

std::string BoardLink::last_error() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return last_error_;
}

}  // namespace robogene::can
