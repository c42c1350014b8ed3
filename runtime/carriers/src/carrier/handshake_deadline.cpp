// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "handshake_deadline.hpp"

#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <condition_variable>
#include <map>
#include <mutex>
#include <set>
#include <thread>

namespace robogene::carrier::detail {

namespace {

using Clock = std::chrono::steady_clock;

// One thread for the whole process, however many handshakes are under way.
class DeadlineTimer {
 public:
  static DeadlineTimer& instance() {
    // Never destroyed: the thread may outlive static destruction at exit.
    static DeadlineTimer* timer = new DeadlineTimer;
    return *timer;
  }

  unsigned long add(int fd, Clock::time_point at) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!started_) {
      std::thread([this] { run(); }).detach();
      started_ = true;
    }
    const unsigned long id = ++next_id_;
    due_.emplace(at, Entry{id, fd});
    cv_.notify_one();
    return id;
  }

  // Forgets `id`; true when its deadline had already fired.
  bool remove(unsigned long id) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = due_.begin(); it != due_.end(); ++it) {
      if (it->second.id == id) {
        due_.erase(it);
        return false;
      }
    }
    return fired_.erase(id) > 0;
  }

  bool fired(unsigned long id) {
    std::lock_guard<std::mutex> lock(mutex_);
    return fired_.count(id) > 0;
  }

 private:
  struct Entry {
    unsigned long id;
    int fd;
  };

  void run() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      if (due_.empty()) {
        cv_.wait(lock);
        continue;
      }
      auto first = due_.begin();
      if (Clock::now() < first->first) {
        // A copy: waiting releases the lock, and remove() may erase the entry (and its key) meanwhile.
        const Clock::time_point when = first->first;
        cv_.wait_until(lock, when);
        continue;
      }
      ::shutdown(first->second.fd, SHUT_RDWR);
      fired_.insert(first->second.id);
      due_.erase(first);
    }
  }

  std::mutex mutex_;
  std::condition_variable cv_;
  std::multimap<Clock::time_point, Entry> due_;
  std::set<unsigned long> fired_;
  unsigned long next_id_ = 0;
  bool started_ = false;
};

}  // namespace

HandshakeDeadline::HandshakeDeadline(int fd, std::chrono::milliseconds within) {
  if (fd < 0 || within.count() <= 0) return;
  dup_fd_ = ::fcntl(fd, F_DUPFD_CLOEXEC, 0);
  if (dup_fd_ < 0) return;  // out of descriptors: the per-read timeouts still apply
  id_ = DeadlineTimer::instance().add(dup_fd_, Clock::now() + within);
}

HandshakeDeadline::~HandshakeDeadline() {
  if (dup_fd_ < 0) return;
  DeadlineTimer::instance().remove(id_);  // before the duplicate closes: its number may be reused
  ::close(dup_fd_);
}

bool HandshakeDeadline::expired() const {
  return dup_fd_ >= 0 && DeadlineTimer::instance().fired(id_);
}

}  // namespace robogene::carrier::detail
