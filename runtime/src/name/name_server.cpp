// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name/name_server.hpp"

#include <cstdio>
#include <string>

#include <sys/socket.h>

#include "robogene/carrier/registry.hpp"
#include "robogene/error.hpp"
#include "robogene/name/name_ser_carrier.hpp"
#include "root_port.hpp"

namespace robogene::name {

struct NameServer::Session {
  net::TcpStream stream;
  std::thread thread;
  std::atomic<bool> finished{false};
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
    if (!accepted) continue;
    std::size_t open;
    {
      std::lock_guard<std::mutex> lock(sessions_mutex_);
      open = sessions_.size();
    }
    if (open >= limits_.max_connections) {
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
                                 [this] { return peers(); }};
    in = carrier::accept_connection(std::move(stream), ctx);
    {
      std::lock_guard<std::mutex> lock(session.peer_mutex);
      session.peer = Peer{in->remote_name(), in->carrier_name()};
      session.connection = in.get();
    }
    if (!stopping_) detail::serve_root_messages(root, *in);
  } catch (const Error& e) {
    if (!stopping_) std::fprintf(stderr, "robogene server: %s: %s\n", peer.c_str(), e.what());
  }
  std::lock_guard<std::mutex> lock(session.peer_mutex);
  session.connection = nullptr;
}

}  // namespace robogene::name
