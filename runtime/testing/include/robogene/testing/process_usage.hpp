// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// What this process holds, read from Linux /proc: threads, open file descriptors, resident
// memory. Hostile-peer tests measure it before an attack and after, once the port has had
// the chance to let go.
#pragma once

#include <dirent.h>

#include <chrono>
#include <cstddef>
#include <fstream>
#include <string>
#include <thread>

namespace robogene::test {

inline std::size_t count_entries(const char* dir) {
  std::size_t n = 0;
  if (DIR* d = ::opendir(dir)) {
    while (dirent* e = ::readdir(d)) {
      if (e->d_name[0] != '.') ++n;
    }
    ::closedir(d);
  }
  return n;
}

struct ProcessUsage {
  std::size_t threads = 0;
  std::size_t fds = 0;
  std::size_t rss_kb = 0;
  std::size_t peak_rss_kb = 0;  // since start or the last reset_peak_rss()

  static ProcessUsage now() {
    ProcessUsage u;
    u.threads = count_entries("/proc/self/task");
    u.fds = count_entries("/proc/self/fd");
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
      if (key == "VmHWM:") {
        status >> u.peak_rss_kb;
      } else if (key == "VmRSS:") {
        status >> u.rss_kb;
        break;
      }
      std::getline(status, key);
    }
    return u;
  }

  // Makes the peak (VmHWM) start again from the current resident size (Linux 4.0 and later).
  static void reset_peak_rss() { std::ofstream("/proc/self/clear_refs") << "5"; }

  std::string text() const {
    return std::to_string(threads) + " threads, " + std::to_string(fds) + " fds, " +
           std::to_string(rss_kb / 1024) + " MB resident (peak " + std::to_string(peak_rss_kb / 1024) + " MB)";
  }
};

// Polls (every 50 ms, up to `limit`) until `condition(ProcessUsage::now())` holds; the last
// measurement either way.
template <typename Condition>
ProcessUsage usage_when(Condition condition, std::chrono::milliseconds limit = std::chrono::milliseconds(5000)) {
  const auto until = std::chrono::steady_clock::now() + limit;
  for (;;) {
    ProcessUsage u = ProcessUsage::now();
    if (condition(u) || std::chrono::steady_clock::now() >= until) return u;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

}  // namespace robogene::test
