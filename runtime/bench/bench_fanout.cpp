// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Fan-out: latency from a write to a reader's callback with 1 reader, then with 8 readers on the
// same output (tcp), for the first and the last reader served; and, in the same run, the same
// fan-out done with raw sockets: one writer thread writes our message's bytes to every reader
// socket, then reads every 8-byte ack; each reader thread reads the message, notes the time and
// writes the ack. No parsing, no ports. Ratios:
//   first_ratio  ours, first of 8 / ours, 1 reader: the target (<= 2), "one reader's latency";
//   last_ratio   ours, last of 8 / ours, 1 reader: for reference;
//   last_vs_raw  ours, last of 8 / raw, last of 8: what the port adds when it serves 8 readers;
//   raw_last     raw, last of 8 / raw, 1 reader: what the machine imposes (9 busy threads on its
//                cores), which no port design can remove.
// Usage: bench_fanout [--n=5000]
#include <atomic>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bench_common.hpp"
#include "robogene/net/tcp_listener.hpp"
#include "robogene/port.hpp"

using namespace robogene;

namespace {

struct Result {
  bench::Summary first, last;
};

using Arrivals = std::vector<std::unique_ptr<std::atomic<std::int64_t>>>;

std::int64_t now_ns() { return bench::Clock::now().time_since_epoch().count(); }

// Collects first/last latencies of message i once every reader has stamped it.
struct Latencies {
  std::vector<double> first, last;
  void add(std::int64_t t0, const Arrivals& arrival) {
    first.push_back((arrival.front()->load() - t0) / 1000.0);
    std::int64_t latest = 0;
    for (auto& a : arrival) latest = std::max(latest, a->load());
    last.push_back((latest - t0) / 1000.0);
  }
  Result result() const { return {bench::summarize(first), bench::summarize(last)}; }
};

Arrivals make_arrivals(int readers) {
  Arrivals a;
  for (int i = 0; i < readers; ++i) a.push_back(std::make_unique<std::atomic<std::int64_t>>(0));
  return a;
}

Result ours(int readers, int n, const Bottle& msg) {
  Port w;
  w.open_at("/bench/fan:o", {"127.0.0.1", 0});
  std::vector<std::unique_ptr<Port>> ports;
  Arrivals arrival = make_arrivals(readers);
  for (int i = 0; i < readers; ++i) {
    ports.push_back(std::make_unique<Port>());
    auto* slot = arrival[i].get();
    ports.back()->open_at("/bench/fan" + std::to_string(i), {"127.0.0.1", 0});
    ports.back()->set_reader([slot](const Bottle&, const MessageInfo&, Bottle*) { slot->store(now_ns()); });
    w.add_output(ports.back()->contact());
  }
  Latencies lat;
  for (int i = 0; i < n + n / 10; ++i) {
    const std::int64_t t0 = now_ns();
    w.write(msg);  // returns once every reader has acked
    if (i >= n / 10) lat.add(t0, arrival);
  }
  return lat.result();
}

// The same exchange over raw sockets: message bytes out to every reader, 8-byte acks back.
Result raw(int readers, int n, std::size_t message_size) {
  auto listener = net::TcpListener::listen({"127.0.0.1", 0});
  Arrivals arrival = make_arrivals(readers);
  std::vector<net::TcpStream> out;
  std::vector<std::thread> threads;
  for (int r = 0; r < readers; ++r) {
    out.push_back(net::TcpStream::connect(listener.local()));
    auto in = listener.accept();
    threads.emplace_back([s = std::move(*in), slot = arrival[r].get(), message_size]() mutable {
      std::vector<char> buf(message_size), ack(8, 0);
      try {
        for (;;) {
          s.read_exact(buf.data(), buf.size());
          slot->store(now_ns());
          s.write_all(ack.data(), ack.size());
        }
      } catch (const std::exception&) {
      }
    });
  }
  std::vector<char> msg(message_size, 1), ack(8);
  Latencies lat;
  for (int i = 0; i < n + n / 10; ++i) {
    const std::int64_t t0 = now_ns();
    for (auto& s : out) s.write_all(msg.data(), msg.size());
    for (auto& s : out) s.read_exact(ack.data(), ack.size());
    if (i >= n / 10) lat.add(t0, arrival);
  }
  for (auto& s : out) s.close();
  for (auto& t : threads) t.join();
  return lat.result();
}

void print(const char* what, const bench::Summary& s) {
  std::printf("  %-24s %8.1f %8.1f\n", what, s.median, s.p99);
}

}  // namespace

int main(int argc, char** argv) {
  const int n = bench::arg_int(argc, argv, "n", 5000);
  const Bottle msg = Bottle::from_text("1 2.5 \"hi\" [set]");
  const std::size_t wire_size = 34 + msg.encoded_size();  // index [8, 46, 0] + PortCommand + bottle
  const Result raw1 = raw(1, n, wire_size);
  const Result raw8 = raw(8, n, wire_size);
  const Result one = ours(1, n, msg);
  const Result eight = ours(8, n, msg);
  std::printf("fan-out latency, write -> reader, %d messages (median / p99, us)\n", n);
  print("raw, 1 reader", raw1.first);
  print("raw, 8 readers, first", raw8.first);
  print("raw, 8 readers, last", raw8.last);
  print("ours, 1 reader", one.first);
  print("ours, 8 readers, first", eight.first);
  print("ours, 8 readers, last", eight.last);
  std::printf("RESULT fanout_first_ratio=%.2f fanout_last_ratio=%.2f fanout_last_vs_raw=%.2f "
              "raw_last_ratio=%.2f target: first<=2.0\n",
              eight.first.median / one.first.median, eight.last.median / one.first.median,
              eight.last.median / raw8.last.median, raw8.last.median / raw1.first.median);
  return 0;
}
