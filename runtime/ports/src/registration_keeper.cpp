// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "registration_keeper.hpp"

#include <algorithm>
#include <exception>

namespace robogene::detail {

RegistrationKeeper& RegistrationKeeper::instance() {
  static RegistrationKeeper* keeper = new RegistrationKeeper;
  return *keeper;
}

void RegistrationKeeper::add(const void* key, std::chrono::milliseconds period, std::function<void()> check) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!started_) {
    std::thread t([this] { run(); });
    thread_id_ = t.get_id();
    t.detach();
    started_ = true;
  }
  entries_.push_back(Entry{key, period, Clock::now() + period, std::move(check)});
  cv_.notify_all();
}

void RegistrationKeeper::remove(const void* key) {
  std::unique_lock<std::mutex> lock(mutex_);
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.key == key; }),
                 entries_.end());
  cv_.notify_all();
  if (std::this_thread::get_id() == thread_id_) return;
  cv_.wait(lock, [&] { return checking_ != key; });
}

void RegistrationKeeper::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    if (entries_.empty()) {
      cv_.wait(lock);
      continue;
    }
    auto next = std::min_element(entries_.begin(), entries_.end(),
                                 [](const Entry& a, const Entry& b) { return a.due < b.due; });
    const Clock::time_point due = next->due;  // a copy: waiting releases the lock
    if (Clock::now() < due) {
      cv_.wait_until(lock, due);
      continue;
    }
    next->due = Clock::now() + next->period;
    checking_ = next->key;
    std::function<void()> check = next->check;  // the entry may go while the check runs
    lock.unlock();
    try {
      check();
    } catch (const std::exception&) {
      // each check reports its own failures; one port's must not stop the others'
    }
    check = nullptr;  // drops what the check holds before the port may be gone
    lock.lock();
    checking_ = nullptr;
    cv_.notify_all();
  }
}

}  // namespace robogene::detail
