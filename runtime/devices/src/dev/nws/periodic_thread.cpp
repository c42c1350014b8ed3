// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/dev/nws/periodic_thread.hpp"

#include <chrono>
#include <exception>

#include "robogene/error.hpp"
#include "robogene/log.hpp"

namespace robogene::dev {

void PeriodicThread::start(double period_seconds, std::function<void()> step) {
  if (!(period_seconds >= 0.0)) throw Error("PeriodicThread: the period must be >= 0 seconds");
  stop();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = false;
  }
  thread_ = std::thread([this, period_seconds, step = std::move(step)] { run(period_seconds, step); });
}

void PeriodicThread::stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  cv_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void PeriodicThread::run(double period_seconds, const std::function<void()>& step) {
  using clock = std::chrono::steady_clock;
  const auto period = std::chrono::duration_cast<clock::duration>(
      std::chrono::duration<double>(period_seconds));
  auto next = clock::now();
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      if (period.count() > 0) cv_.wait_until(lock, next, [this] { return stopping_; });
      if (stopping_) return;
    }
    try {
      step();
    } catch (const std::exception& e) {
      log::warn("periodic", std::string("a publishing step failed: ") + e.what());
    }
    if (period.count() > 0) {
      next += period;
      const auto now = clock::now();
      if (next < now) next += ((now - next) / period + 1) * period;  // skip missed ticks
    }
  }
}

}  // namespace robogene::dev
