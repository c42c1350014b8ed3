// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name/name_server.hpp"

#include <cstdio>
#include <string>

#include "name_sessions.hpp"
#include "robogene/error.hpp"
#include "robogene/net/stream_reader.hpp"
#include "yarp_wire.hpp"

namespace robogene::name {

struct NameServer::Session {
  net::TcpStream stream;
  std::thread thread;
  std::atomic<bool> finished{false};
  std::mutex peer_mutex;
  Peer peer;
};

NameServer::NameServer(NameService& service, const net::Endpoint& at, NameServerLimits limits)
    : service_(service), limits_(limits), listener_(net::TcpListener::listen(at)) {}

NameServer::NameServer(NameService& service, net::TcpListener listener, NameServerLimits limits)
    : service_(service), limits_(limits), listener_(std::move(listener)) {}

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
  for (auto& s : sessions_) s->stream.shutdown();
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
  try {
    stream.set_read_timeout(net::Millis{limits_.handshake_timeout_ms});
    stream.set_write_timeout(net::Millis{limits_.write_timeout_ms});
    net::StreamReader reader(stream);
    detail::SessionContext context{
        service_,
        limits_,
        stream,
        reader,
        "tcp://" + service_.config().host + ":" + std::to_string(service_.config().port) + "/",
        [&session](const std::string& name, const std::string& carrier) {
          std::lock_guard<std::mutex> lock(session.peer_mutex);
          session.peer = Peer{name, carrier};
        },
        [this] { return peers(); },
    };
    if (!reader.wait_for_data()) return;  // connected and left: a port-presence check
    wire::Header header;
    reader.read_exact(header.data(), header.size());
    auto number = wire::read_yarp_number(header);
    if (wire::starts_with(header, "NAME_SER")) {
      detail::serve_name_ser(context, header);
    } else if (wire::starts_with(header, "CONNECT ")) {
      detail::serve_text(context, false);
    } else if (wire::starts_with(header, "CONNACK ")) {
      detail::serve_text(context, true);
    } else if (number && *number == wire::kTcpSpecifier) {
      detail::serve_tcp(context, true);
    } else if (number && *number == wire::kFastTcpSpecifier) {
      detail::serve_tcp(context, false);
    } else {
      detail::refuse_unknown_carrier(context, header);
    }
  } catch (const Error& e) {
    if (!stopping_) std::fprintf(stderr, "robogene server: %s: %s\n", stream.peer_text().c_str(), e.what());
  }
}

}  // namespace robogene::name
