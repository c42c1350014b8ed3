// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// One thread for the whole process that runs each open port's registration check (does the
// name server still know it?) at that port's period: a process with a hundred ports keeps one
// thread for this, not a hundred (private to src/port).
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace robogene::detail {

class RegistrationKeeper {
 public:
  // Never destroyed: its thread may outlive static destruction at exit.
  static RegistrationKeeper& instance();

  // Runs `check` every `period` (the first time one period from now) until remove(key).
  void add(const void* key, std::chrono::milliseconds period, std::function<void()> check);
  // Forgets `key`. When it returns, that check is not running and will not run again (called
  // from inside the check itself, it cannot wait for it to end).
  void remove(const void* key);

 private:
  using Clock = std::chrono::steady_clock;
  struct Entry {
    const void* key;
    std::chrono::milliseconds period;
    Clock::time_point due;
    std::function<void()> check;
  };

  void run();

  std::mutex mutex_;
  std::condition_variable cv_;  // entries changed, or a check ended
  std::vector<Entry> entries_;
  const void* checking_ = nullptr;
  bool started_ = false;
  std::thread::id thread_id_;
};

}  // namespace robogene::detail
