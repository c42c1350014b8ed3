// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name/name_server.hpp"

#include <chrono>
#include <cstdio>
#include <string>

#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

#include "robogene/carrier/registry.hpp"
#include "robogene/error.hpp"
#include "robogene/name/name_ser_carrier.hpp"
#include "root_port.hpp"

namespace robogene::name {

namespace {
std::int64_t now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}
}  // namespace

struct NameServer::Session {
  net::TcpStream stream;
  std::thread thread;
  std::atomic<bool> finished{false};
  std::atomic<std::int64_t> last_heard{now_ms()};  // connection or last message
  std::atomic<bool> told_to_leave{false};
  // A duplicate of the socket, so that the session can be told to leave during its handshake
  // too (the stream itself moves into the handshake); closed when the session ends.
  int watch_fd = -1;
  std::mutex peer_mutex;
  Peer peer;
  carrier::InboundConnection* connection = nullptr;  // once the handshake is done; for stop()
};

NameServer::NameServer(NameService& service, const net::Endpoint& at, NameServerLimits limits)
    : NameServer(service, net::TcpListener::listen(at), limits) {}

NameServer::NameServer(NameService& service, net::TcpListener listener, NameServerLimits limits)
    : service_(service), limits_(limits), listener_(std::move(listener)) {
  // /root is reached by YARP clients with name_ser as well as with every ordinary carrier.
  carrier::CarrierRegistry::global().add(make_name_ser_carrier());
}

NameServer::~NameServer() {
  stop();
  std::lock_guard<std::mutex> lock(sessions_mutex_);
  for (auto& s : sessions_) {
    if (s->thread.joinable()) s->thread.join();
  }
}

void NameServer::tell_to_leave(Session& s) {
  s.told_to_leave = true;
  std::lock_guard<std::mutex> p(s.peer_mutex);
  if (s.connection) {
    s.connection->interrupt();
  } else if (s.watch_fd >= 0) {
    ::shutdown(s.watch_fd, SHUT_RDWR);
  } else {
    s.stream.shutdown();
  }
}

void NameServer::drop_idle() {
  if (limits_.idle_timeout_ms <= 0) return;
  const std::int64_t now = now_ms();
  std::lock_guard<std::mutex> lock(sessions_mutex_);
  for (auto& s : sessions_) {
    if (s->finished || s->told_to_leave) continue;
    if (now - s->last_heard > limits_.idle_timeout_ms) tell_to_leave(*s);
  }
}

bool NameServer::make_room() {
  std::lock_guard<std::mutex> lock(sessions_mutex_);
  std::size_t open = 0;
  Session* idlest = nullptr;
  for (auto& s : sessions_) {
    if (s->finished || s->told_to_leave) continue;
    ++open;
    if (!idlest || s->last_heard < idlest->last_heard) idlest = s.get();
  }
  if (open < limits_.max_connections) return true;
  // Sessions told to leave are still winding down; a few of them are fine, a pile is not.
  if (!idlest || sessions_.size() >= limits_.max_connections + kLeavingSlack) return false;
  tell_to_leave(*idlest);
  return true;
}

void NameServer::stop() noexcept {
  stopping_ = true;
  listener_.interrupt();
  std::lock_guard<std::mutex> lock(sessions_mutex_);
  for (auto& s : sessions_) {
    std::lock_guard<std::mutex> p(s->peer_mutex);
    if (s->connection) {
      s->connection->interrupt();
    } else {
      s->stream.shutdown();
    }
  }
}

std::vector<NameServer::Peer> NameServer::peers() {
  std::vector<Peer> out;
  std::lock_guard<std::mutex> lock(sessions_mutex_);
  for (auto& s : sessions_) {
    if (s->finished) continue;
    std::lock_guard<std::mutex> p(s->peer_mutex);
    if (!s->peer.carrier.empty()) out.push_back(s->peer);
  }
  return out;
}

void NameServer::reap_finished() {
  std::lock_guard<std::mutex> lock(sessions_mutex_);
  for (auto it = sessions_.begin(); it != sessions_.end();) {
    if ((*it)->finished) {
      (*it)->thread.join();
      it = sessions_.erase(it);
    } else {
      ++it;
    }
  }
}

void NameServer::run() {
  while (!stopping_) {
    std::optional<net::TcpStream> accepted;
    try {
      accepted = listener_.accept(net::Millis{1000});
    } catch (const NetworkError& e) {
      std::fprintf(stderr, "robogene server: accept failed: %s\n", e.what());
      continue;
    }
    reap_finished();
    drop_idle();
    if (!accepted) continue;
    if (!make_room()) {
      static const char busy[] = "*** error: the name server is serving too many connections; try again\r\n";
      try {
        accepted->set_write_timeout(net::Millis{1000});
        accepted->write_all(busy, sizeof busy - 1);
      } catch (const NetworkError&) {
      }
      continue;
    }
    auto session = std::make_unique<Session>();
    session->stream = std::move(*accepted);
    Session* raw = session.get();
    {
      std::lock_guard<std::mutex> lock(sessions_mutex_);
      sessions_.push_back(std::move(session));
    }
    raw->thread = std::thread([this, raw] {
      serve(*raw);
      raw->stream.close();
      raw->finished = true;
    });
  }
}

void NameServer::serve(Session& session) {
  net::TcpStream& stream = session.stream;
  const std::string peer = stream.peer_text();
  std::unique_ptr<carrier::InboundConnection> in;  // outlives the pointer stop() may use
  {
    std::lock_guard<std::mutex> lock(session.peer_mutex);
    session.watch_fd = ::fcntl(stream.fd(), F_DUPFD_CLOEXEC, 0);
  }
  struct CloseWatch {
    Session& s;
    ~CloseWatch() {
      std::lock_guard<std::mutex> lock(s.peer_mutex);
      s.connection = nullptr;
      if (s.watch_fd >= 0) ::close(s.watch_fd);
      s.watch_fd = -1;
    }
  } close_watch{session};  // destroyed before `in`
  try {
    stream.set_write_timeout(net::Millis{limits_.write_timeout_ms});
    // A peer that connects and leaves without a byte is checking that we are alive: not an error.
    if (!stream.wait_readable(net::Millis{limits_.handshake_timeout_ms})) return;
    char first;
    if (::recv(stream.fd(), &first, 1, MSG_PEEK) <= 0) return;

    carrier::AcceptContext ctx;
    ctx.local_name = "/root";
    ctx.max_message_size = limits_.max_message;
    ctx.max_line_length = limits_.max_line;
    ctx.handshake_timeout = net::Millis{limits_.handshake_timeout_ms};
    ctx.access = access_;
    ctx.harmless_data = &NameService::is_read_only;
    detail::RootPortContext root{service_, stream.peer().host,
                                 "tcp://" + service_.config().host + ":" + std::to_string(service_.config().port) + "/",
                                 [this] { return peers(); },
                                 [&session] { session.last_heard = now_ms(); }};
    in = carrier::accept_connection(std::move(stream), ctx);
    session.last_heard = now_ms();
    {
      std::lock_guard<std::mutex> lock(session.peer_mutex);
      session.peer = Peer{in->remote_name(), in->carrier_name()};
      session.connection = in.get();
    }
    if (!stopping_) detail::serve_root_messages(root, *in);
  } catch (const Error& e) {
    if (!stopping_) std::fprintf(stderr, "robogene server: %s: %s\n", peer.c_str(), e.what());
  }
}

}  // namespace robogene::name
