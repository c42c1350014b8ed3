// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Fan-out: latency from Port::write to a reader's callback with 1 reader, then with 8 readers
// on the same output port (tcp). Reported for the first and the last reader served. Target:
// with 8 readers a reader's latency stays within 2x of the single-reader case.
// Usage: bench_fanout [--n=5000]
#include <atomic>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "robogene/port.hpp"

using namespace robogene;

namespace {

struct Result {
  bench::Summary first, last;
};

Result run(int readers, int n) {
  Port w;
  w.open_at("/bench/fan:o", {"127.0.0.1", 0});
  std::vector<std::unique_ptr<Port>> ports;
  std::vector<std::unique_ptr<std::atomic<std::int64_t>>> arrival;
  for (int i = 0; i < readers; ++i) {
    ports.push_back(std::make_unique<Port>());
    arrival.push_back(std::make_unique<std::atomic<std::int64_t>>(0));
    auto* slot = arrival.back().get();
    ports.back()->open_at("/bench/fan" + std::to_string(i), {"127.0.0.1", 0});
    ports.back()->set_reader([slot](const Bottle&, const MessageInfo&, Bottle*) {
      slot->store(bench::Clock::now().time_since_epoch().count());
    });
    w.add_output(ports.back()->contact());
  }
  Bottle msg = Bottle::from_text("1 2.5 \"hi\" [set]");
  std::vector<double> first, last;
  for (int i = 0; i < n + n / 10; ++i) {
    auto start = bench::Clock::now();
    w.write(msg);
    if (i < n / 10) continue;
    auto t0 = start.time_since_epoch().count();
    first.push_back((arrival.front()->load() - t0) / 1000.0);
    std::int64_t latest = 0;
    for (auto& a : arrival) latest = std::max(latest, a->load());
    last.push_back((latest - t0) / 1000.0);
  }
  return {bench::summarize(first), bench::summarize(last)};
}

}  // namespace

int main(int argc, char** argv) {
  int n = bench::arg_int(argc, argv, "n", 5000);
  Result one = run(1, n);
  Result eight = run(8, n);
  std::printf("fan-out latency, write -> reader callback, %d messages (median / p99, us)\n", n);
  std::printf("  1 reader             %8.1f %8.1f\n", one.first.median, one.first.p99);
  std::printf("  8 readers, first     %8.1f %8.1f   ratio %.2f\n", eight.first.median,
              eight.first.p99, eight.first.median / one.first.median);
  std::printf("  8 readers, last      %8.1f %8.1f   ratio %.2f\n", eight.last.median,
              eight.last.p99, eight.last.median / one.first.median);
  std::printf("RESULT fanout_first_ratio=%.2f fanout_last_ratio=%.2f target<=2.0\n",
              eight.first.median / one.first.median, eight.last.median / one.first.median);
  return 0;
}
