// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene server`: the name server /root, with registrations kept in SQLite.
#include <algorithm>
#include <cstdio>
#include <string>

#include "commands.hpp"
#include "robogene/error.hpp"
#include "robogene/name/local_name_server.hpp"
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
  name::LocalNameServerOptions options;
  options.at = net::Endpoint{ip, port};
  options.db = db_path;
  options.service = config;
  options.limits = limits;
  options.probe_liveness = true;
  options.sweep_seconds = sweep_seconds;
  options.on_dropped = [](const std::string& gone) {
    std::fprintf(stderr, "robogene server: dropped stale registration %s\n", gone.c_str());
  };
  // The multicast fallback lets programs without yarp.conf find us (`robogene detect`, `yarp
  // detect`); like yarpserver, it is registered as "fallback". Without multicast we still serve.
  options.fallback = fallback;
  name::LocalNameServer server(options);
  if (fallback && !server.fallback_running()) {
    std::fprintf(stderr, "robogene server: no multicast fallback (%s); clients need yarp.conf or --server\n",
                 server.fallback_error().c_str());
  }
  if (write_conf) write_yarp_conf(server.contact());

  std::printf("Name server /root is listening at tcp://%s:%d/ (registrations kept in %s)\n", ip.c_str(),
              server.contact().port, db_path.c_str());
  std::fflush(stdout);
  wait_for_shutdown_signal();
  server.stop();
  std::printf("Name server stopped\n");
  return 0;
}

}  // namespace robogene::cli
