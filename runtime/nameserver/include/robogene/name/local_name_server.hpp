// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A name server in this process, in one line: `name::LocalNameServer ns;` binds a free loopback
// port, serves /root from a thread of its own until destroyed, and tells where it is
// (`ns.contact()`, `ns.client()`). `robogene server`, the tests and the Python binding all start
// their name servers this way; the options cover what the CLI sets (address, database, liveness
// probe, periodic sweep, multicast fallback, limits).
#pragma once

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "robogene/name/fallback.hpp"
#include "robogene/name/liveness.hpp"
#include "robogene/name/name_server.hpp"
#include "robogene/name/name_service.hpp"
#include "robogene/name/registry.hpp"
#include "robogene/name_client.hpp"
#include "robogene/net/endpoint.hpp"

namespace robogene::name {

struct LocalNameServerOptions {
  net::Endpoint at{"127.0.0.1", 0};  // port 0: a free one, chosen by the system
  std::string db = ":memory:";       // the SQLite file registrations are kept in
  // Registration numbering, grace and recheck; host and port are set to where the server is.
  NameServiceConfig service;
  NameServerLimits limits;
  // Probe registered ports over tcp and drop the ones proven gone (the CLI's behaviour). Off:
  // no entry is ever stale.
  bool probe_liveness = false;
  int probe_connect_timeout_ms = 1000;
  int probe_answer_timeout_ms = 2000;
  // Sweep stale entries this often even when nobody asks (0 = never), telling `on_dropped`
  // each name that went (unset: logged at info level).
  double sweep_seconds = 0;
  std::function<void(const std::string& name)> on_dropped;
  // Answer `NAME_SERVER ...` datagrams on the multicast fallback group (registered as
  // "fallback"). A network without multicast is no error: fallback_error() says why.
  bool fallback = false;
  net::Endpoint fallback_group = name::fallback_group();
};

class LocalNameServer {
 public:
  // Binds and starts serving; throws NetworkError naming the address when it cannot bind and
  // robogene::Error naming the file when the database cannot be opened.
  explicit LocalNameServer(LocalNameServerOptions options = {});
  // Stops serving, closes every session and joins the threads.
  ~LocalNameServer();
  LocalNameServer(const LocalNameServer&) = delete;
  LocalNameServer& operator=(const LocalNameServer&) = delete;

  // Where /root listens (the bound port, never 0).
  const net::Endpoint& contact() const noexcept { return contact_; }
  // "127.0.0.1:10000", as the CLI's --server and a device's (server ...) option take it.
  std::string address() const { return contact_.to_string(); }
  NameClient client(net::Millis timeout = net::Millis{5000}) const { return NameClient(contact_, timeout); }

  NameService& service() noexcept { return *service_; }
  Registry& registry() noexcept { return registry_; }
  NameServer& server() noexcept { return *server_; }
  // Whether the multicast fallback answers, and why not when it was asked for and does not.
  bool fallback_running() const noexcept { return responder_ != nullptr; }
  const std::string& fallback_error() const noexcept { return fallback_error_; }

  // Stops serving now (the destructor does it too); safe to call twice.
  void stop() noexcept;

 private:
  void sweep_until_stopped(double seconds, const std::function<void(const std::string&)>& on_dropped);

  Registry registry_;
  net::Endpoint contact_;
  std::unique_ptr<LivenessProbe> probe_;
  std::unique_ptr<NameService> service_;
  std::unique_ptr<NameServer> server_;
  std::unique_ptr<FallbackResponder> responder_;
  std::string fallback_error_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread serving_;
  std::thread sweeper_;
};

}  // namespace robogene::name
