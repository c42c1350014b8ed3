// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/buffered_port.hpp"

namespace robogene {

BufferedPort::BufferedPort(BufferPolicy policy, std::size_t strict_capacity, PortOptions options)
    : policy_(policy), capacity_(strict_capacity ? strict_capacity : 1), port_(options) {
  port_.set_reader([this](const Bottle& b, const MessageInfo& info, Bottle*) { on_message(b, info); });
}

BufferedPort::~BufferedPort() { close(); }

void BufferedPort::close() {
  port_.close();
  std::lock_guard<std::mutex> lock(mutex_);
  closed_ = true;
  cv_.notify_all();
}

void BufferedPort::on_message(const Bottle& b, const MessageInfo& info) {
  Callback cb;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    cb = callback_;
    if (!cb) {
      if (policy_ == BufferPolicy::LatestOnly) {
        dropped_ += queue_.size();
        queue_.clear();
      } else if (queue_.size() >= capacity_) {
        // Strict but bounded: the oldest message goes, so memory cannot grow without limit.
        queue_.pop_front();
        ++dropped_;
      }
      queue_.emplace_back(b, info);
      cv_.notify_one();
      return;
    }
  }
  cb(b, info);
}

Bottle& BufferedPort::prepare() {
  prepared_.clear();
  return prepared_;
}

bool BufferedPort::write() { return port_.write(prepared_); }

std::optional<Bottle> BufferedPort::read(net::Millis timeout, MessageInfo* info) {
  std::unique_lock<std::mutex> lock(mutex_);
  auto ready = [&] { return closed_ || !queue_.empty(); };
  if (timeout.count() > 0) {
    if (!cv_.wait_for(lock, timeout, ready)) return std::nullopt;
  } else {
    cv_.wait(lock, ready);
  }
  if (queue_.empty()) return std::nullopt;
  auto item = std::move(queue_.front());
  queue_.pop_front();
  if (info) *info = std::move(item.second);
  return std::move(item.first);
}

std::optional<Bottle> BufferedPort::poll(MessageInfo* info) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (queue_.empty()) return std::nullopt;
  auto item = std::move(queue_.front());
  queue_.pop_front();
  if (info) *info = std::move(item.second);
  return std::move(item.first);
}

std::size_t BufferedPort::pending() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return queue_.size();
}

std::size_t BufferedPort::dropped() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return dropped_;
}

void BufferedPort::set_callback(Callback cb) {
  std::lock_guard<std::mutex> lock(mutex_);
  callback_ = std::move(cb);
}

}  // namespace robogene
