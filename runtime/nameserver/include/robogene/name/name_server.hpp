// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The name server on the network: the port /root, reachable with every carrier YARP 3 clients and
// people use (reference section 4): raw `NAME_SERVER ...` lines (the name_ser carrier), the text
// carriers `CONNECT ` / `CONNACK ` (so telnet works, paper section 4.4), and binary tcp /
// fast_tcp (`bot ...` for Bottle replies). Each connection is served by its own thread; YARP
// clients open one connection per request.
#pragma once

#include <atomic>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "robogene/access_policy.hpp"
#include "robogene/name/name_service.hpp"
#include "robogene/net/endpoint.hpp"
#include "robogene/net/tcp_listener.hpp"

namespace robogene::name {

struct NameServerLimits {
  // Sessions served at once. At the limit a new connection makes the session that has been
  // idle longest leave (YARP clients open one short connection per request, so an old idle
  // session is a forgotten telnet or a flood); only if none can leave is it refused.
  std::size_t max_connections = 256;
  std::size_t max_line = 64 * 1024;          // one text command
  std::size_t max_message = 1024 * 1024;     // one binary message
  int handshake_timeout_ms = 10000;          // each read of the handshake; the whole of it is
                                             // bounded by ResourceLimits::handshake_deadline
  int idle_timeout_ms = 10 * 60 * 1000;      // between commands of a session (0 = none)
  int write_timeout_ms = 10000;              // a peer that does not read is dropped
};

class NameServer {
 public:
  // Binds `at` (throws NetworkError naming the address when it cannot).
  NameServer(NameService& service, const net::Endpoint& at, NameServerLimits limits = {});
  // Serves on a socket already bound (so that a server on port 0 can learn its number first).
  NameServer(NameService& service, net::TcpListener listener, NameServerLimits limits = {});
  ~NameServer();
  NameServer(const NameServer&) = delete;
  NameServer& operator=(const NameServer&) = delete;

  const net::Endpoint& local() const noexcept { return listener_.local(); }

  // Serves connections until stop() is called (from another thread or a signal watcher).
  void run();
  // Makes run() return; open sessions are closed and joined.
  void stop() noexcept;

  // A live inbound connection, for `*` (describe) and admin `[list] [in]`.
  struct Peer {
    std::string name;     // the sender name given in the handshake
    std::string carrier;  // "text", "text_ack", "tcp", "fast_tcp", "name_ser"
  };
  std::vector<Peer> peers();

 private:
  struct Session;
  void serve(Session& session);
  void reap_finished();
  // Interrupts `s` (its thread then ends and is reaped).
  void tell_to_leave(Session& s);
  // Ends sessions idle longer than idle_timeout_ms.
  void drop_idle();
  // At max_connections, tells the idlest session to leave; false when the new connection must
  // be refused instead (too many sessions still winding down).
  bool make_room();
  static constexpr std::size_t kLeavingSlack = 64;

  NameService& service_;
  NameServerLimits limits_;
  // HTTP writes (register... from a browser) follow $ROBOGENE_ALLOW / $ROBOGENE_HTTP_WRITES;
  // requests that only read are served to browsers regardless.
  AccessPolicy access_ = AccessPolicy::from_environment();
  net::TcpListener listener_;
  std::atomic<bool> stopping_{false};
  std::mutex sessions_mutex_;
  std::list<std::unique_ptr<Session>> sessions_;
};

}  // namespace robogene::name
