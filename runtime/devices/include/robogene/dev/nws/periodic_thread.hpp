// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A thread that runs a step every period on a fixed schedule (ticks at start + k * period, so
// the rate does not drift with the time a step takes; a step that overruns skips the ticks it
// missed), until stop(). Used by the wrappers to publish their state ports.
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace robogene::dev {

class PeriodicThread {
 public:
  PeriodicThread() = default;
  ~PeriodicThread() { stop(); }
  PeriodicThread(const PeriodicThread&) = delete;
  PeriodicThread& operator=(const PeriodicThread&) = delete;

  // period > 0 seconds: ticks on the schedule; period == 0: steps back to back (a step that
  // waits by itself, such as a camera's getImage, sets the pace).
  void start(double period_seconds, std::function<void()> step);
  // Returns once the current step (if any) has finished. Idempotent.
  void stop();

 private:
  void run(double period_seconds, const std::function<void()>& step);

  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool stopping_ = false;
};

}  // namespace robogene::dev
