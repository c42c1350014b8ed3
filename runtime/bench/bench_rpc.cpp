// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Small-bottle RPC round trip over tcp (`1 2.5 "hi" [set]`, 46 bytes), against a raw-socket
// echo of the same request and reply sizes measured in the same run. Target: ours <= 2x raw.
// Usage: bench_rpc [--n=20000]
#include <cstdio>
#include <thread>
#include <vector>

#include "bench_common.hpp"
#include "robogene/carrier/encoded_payload.hpp"
#include "robogene/net/tcp_listener.hpp"
#include "robogene/rpc.hpp"

using namespace robogene;

namespace {

// Raw baseline: the client writes the bytes our client writes (index + command + bottle), the
// server reads them and writes back the bytes ours writes (reply + ack). No parsing at all.
bench::Summary raw_echo(int n, std::size_t request_size, std::size_t reply_size) {
  auto listener = net::TcpListener::listen({"127.0.0.1", 0});
  std::thread server([&] {
    auto s = listener.accept();
    std::vector<char> in(request_size), out(reply_size, 1);
    try {
      for (;;) {
        s->read_exact(in.data(), in.size());
        s->write_all(out.data(), out.size());
      }
    } catch (const std::exception&) {
    }
  });
  auto c = net::TcpStream::connect(listener.local());
  std::vector<char> req(request_size, 2), rep(reply_size);
  std::vector<double> t;
  t.reserve(n);
  for (int i = 0; i < n + n / 10; ++i) {
    auto start = bench::Clock::now();
    c.write_all(req.data(), req.size());
    c.read_exact(rep.data(), rep.size());
    if (i >= n / 10) t.push_back(bench::micros(bench::Clock::now() - start));
  }
  c.close();
  server.join();
  return bench::summarize(t);
}

bench::Summary ours(int n, const char* carrier) {
  RpcServer server;
  server.open_at("/bench/rpc:i", {"127.0.0.1", 0});
  server.serve([](const Bottle& b, const MessageInfo&) { return b; });
  RpcClient client;
  client.open_at("/bench/rpc:o", {"127.0.0.1", 0});
  Contact to = server.port().contact();
  to.carrier = carrier;
  client.connect(to);
  Bottle cmd = Bottle::from_text("1 2.5 \"hi\" [set]");
  std::vector<double> t;
  t.reserve(n);
  for (int i = 0; i < n + n / 10; ++i) {
    auto start = bench::Clock::now();
    Bottle r = client.call(cmd);
    if (i >= n / 10) t.push_back(bench::micros(bench::Clock::now() - start));
  }
  return bench::summarize(t);
}

}  // namespace

int main(int argc, char** argv) {
  int n = bench::arg_int(argc, argv, "n", 20000);
  Bottle cmd = Bottle::from_text("1 2.5 \"hi\" [set]");
  std::size_t request = 34 + cmd.encoded_size();  // index [8, 46, 0] + PortCommand + bottle
  std::size_t reply = cmd.encoded_size() + 8;     // raw reply + ack
  auto raw = raw_echo(n, request, reply);
  auto tcp = ours(n, "tcp");
  auto fast = ours(n, "fast_tcp");
  std::printf("rpc round trip, %d calls, request %zu B, reply %zu B (median / p99 / min, us)\n", n,
              request, reply);
  std::printf("  raw socket echo   %8.1f %8.1f %8.1f\n", raw.median, raw.p99, raw.min);
  std::printf("  robogene tcp      %8.1f %8.1f %8.1f   ratio %.2f\n", tcp.median, tcp.p99, tcp.min,
              tcp.median / raw.median);
  std::printf("  robogene fast_tcp %8.1f %8.1f %8.1f   ratio %.2f\n", fast.median, fast.p99,
              fast.min, fast.median / raw.median);
  std::printf("RESULT rpc_ratio=%.2f target<=2.0\n", tcp.median / raw.median);
  return 0;
}
