// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The name server's commands (reference section 4.2): `help`, `list`, `register`, `unregister`,
// `query`, `set`, `get`, `check`, `route`, `announce`, `runners`, `gc`, with an optional
// `NAME_SERVER` and/or `bot` prefix. Pure request -> reply logic over a Registry; the transports
// (name_ser, text, text_ack, tcp) live in name_server.hpp.
#pragma once

#include <chrono>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "robogene/bottle.hpp"
#include "robogene/name/liveness.hpp"
#include "robogene/name/name_reply.hpp"
#include "robogene/name/registry.hpp"

namespace robogene::name {

struct NameServiceConfig {
  std::string host = "127.0.0.1";  // where /root itself is reachable
  int port = 10000;
  // Port numbers handed out for `register /x` come from [port + 2, port + 9999] (yarpserver's range).
  int first_offset = 2;
  int last_offset = 9999;
  // A registration younger than this is never probed: its owner may not be listening yet.
  double stale_grace_seconds = 5.0;
  // A registration found alive is not probed again for this long.
  double recheck_seconds = 1.0;
};

class NameService {
 public:
  // Registers /root at config.host:config.port (replacing what a previous run stored). `probe`
  // may be null: then nothing is ever considered stale.
  NameService(Registry& registry, NameServiceConfig config, LivenessProbe* probe);

  // Applies one request. `remote_host` is the peer IP of the requesting connection (used for
  // `register /x` without an address, as yarpserver does). Never throws for bad requests: they
  // get an error reply naming the item at fault.
  NameReply apply(const Bottle& request, const std::string& remote_host);

  // Probes every registration past its grace period and drops the dead ones; returns the names
  // dropped. Called periodically by the server and by the `gc` command.
  std::vector<std::string> sweep();

  // Whether `request` only reads (help, list, query, get, check, route, runners, with or without
  // the NAME_SERVER / bot prefixes). Transports that cannot tell who sent a request (the
  // multicast fallback, a browser's HTTP request) serve only these (docs/security.md).
  static bool is_read_only(const Bottle& request);

  const NameServiceConfig& config() const noexcept { return config_; }

 private:
  struct Request;
  NameReply cmd_help(const Request& r);
  NameReply cmd_list(const Request& r);
  NameReply cmd_query(const Request& r);
  NameReply cmd_register(const Request& r);
  NameReply cmd_unregister(const Request& r);
  NameReply cmd_set(const Request& r);
  NameReply cmd_get(const Request& r);
  NameReply cmd_check(const Request& r);
  NameReply cmd_route(const Request& r);
  NameReply cmd_announce(const Request& r);
  NameReply cmd_runners(const Request& r);
  NameReply cmd_gc(const Request& r);

  NameReply describe(const std::vector<Registration>& regs, bool bottle_mode, bool listing);
  NameReply error(const Request& r, const std::string& message);
  // Drops those of `regs` whose owner is gone; returns the ones still registered.
  std::vector<Registration> drop_stale(std::vector<Registration> regs);
  bool probe_applies(const Registration& r) const;

  Registry& registry_;
  NameServiceConfig config_;
  LivenessProbe* probe_;
  std::mutex mutex_;  // serialises read-modify-write commands (register, set...)
  std::mutex seen_mutex_;
  std::map<std::string, std::chrono::steady_clock::time_point> seen_alive_;
};

}  // namespace robogene::name
