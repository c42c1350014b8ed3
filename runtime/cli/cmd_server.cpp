// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene server`: the name server /root, with registrations kept in SQLite.
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <memory>
#include <mutex>
#include <thread>

#include "commands.hpp"
#include "robogene/error.hpp"
#include "robogene/name/fallback.hpp"
#include "robogene/name/name_server.hpp"
#include "robogene/name/name_service.hpp"
#include "robogene/name/registry.hpp"
#include "robogene/name/tcp_liveness_probe.hpp"
#include "robogene/net/tcp_listener.hpp"
#include "yarp_conf.hpp"

namespace robogene::cli {

int cmd_server(Args& args) {
  std::string ip = args.option("--ip").value_or("127.0.0.1");
  int port = static_cast<int>(parse_number(args.option("--socket").value_or("10000"), "--socket", 0, 65535));
  std::string db_path = args.option("--db").value_or(config_dir() + "/robogene-names.db");
  name::NameServiceConfig config;
  if (auto g = args.option("--stale-grace")) config.stale_grace_seconds = parse_seconds(*g, "--stale-grace");
  if (auto r = args.option("--recheck")) config.recheck_seconds = parse_seconds(*r, "--recheck");
  double sweep_seconds = 60;
  if (auto s = args.option("--sweep")) sweep_seconds = parse_seconds(*s, "--sweep");
  bool write_conf = !args.flag("--read");
  bool fallback = !args.flag("--no-fallback");
  name::NameServerLimits limits;
  if (auto m = args.option("--max-message")) {
    limits.max_message = parse_bytes(*m, "--max-message");
    limits.max_line = std::min(limits.max_line, limits.max_message);
  }
  if (auto c = args.option("--max-connections")) {
    limits.max_connections = static_cast<std::size_t>(parse_number(*c, "--max-connections", 1, 100000));
  }
  if (auto t = args.option("--idle-timeout")) {
    // Capped at 24 days, what an int of milliseconds holds.
    limits.idle_timeout_ms = static_cast<int>(std::min(parse_seconds(*t, "--idle-timeout"), 2000000.0) * 1000);
  }
  if (!args.positional().empty()) throw UsageError("unexpected argument \"" + args.positional()[0] + "\"");

  if (db_path != ":memory:") {
    auto slash = db_path.rfind('/');
    if (slash != std::string::npos && slash > 0) ensure_directory(db_path.substr(0, slash));
  }
  name::Registry registry(db_path);
  net::TcpListener listener = net::TcpListener::listen(net::Endpoint{ip, port});
  config.host = ip;
  config.port = listener.local().port;
  name::TcpLivenessProbe probe;
  name::NameService service(registry, config, &probe);
  name::NameServer server(service, std::move(listener), limits);
  if (write_conf) write_yarp_conf(net::Endpoint{ip, config.port});
  // The multicast fallback lets programs without yarp.conf find us (`robogene detect`, `yarp
  // detect`); like yarpserver, it is registered as "fallback". Without multicast we still serve.
  std::unique_ptr<name::FallbackResponder> responder;
  if (fallback) {
    try {
      responder = std::make_unique<name::FallbackResponder>(service, ip);
      const net::Endpoint& g = responder->group();
      registry.put(name::Registration{"fallback", "mcast", g.host, g.port, "*", 0});
    } catch (const NetworkError& e) {
      std::fprintf(stderr, "robogene server: no multicast fallback (%s); clients need yarp.conf or --server\n",
                   e.what());
    }
  }
  if (!responder) registry.remove("fallback");

  std::mutex mutex;
  std::condition_variable wake;
  bool stopping = false;
  // Periodic sweep, so that stale entries go even when nobody asks about them.
  std::thread sweeper([&] {
    if (sweep_seconds <= 0) return;
    std::unique_lock<std::mutex> lock(mutex);
    while (!wake.wait_for(lock, std::chrono::duration<double>(sweep_seconds), [&] { return stopping; })) {
      lock.unlock();
      for (const auto& gone : service.sweep()) {
        std::fprintf(stderr, "robogene server: dropped stale registration %s\n", gone.c_str());
      }
      lock.lock();
    }
  });
  std::thread serving([&] { server.run(); });

  std::printf("Name server /root is listening at tcp://%s:%d/ (registrations kept in %s)\n", ip.c_str(), config.port,
              db_path.c_str());
  std::fflush(stdout);
  wait_for_shutdown_signal();
  responder.reset();
  server.stop();
  serving.join();
  {
    std::lock_guard<std::mutex> lock(mutex);
    stopping = true;
  }
  wake.notify_all();
  sweeper.join();
  std::printf("Name server stopped\n");
  return 0;
}

}  // namespace robogene::cli
