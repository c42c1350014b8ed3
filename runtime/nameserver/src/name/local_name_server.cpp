// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name/local_name_server.hpp"

#include <chrono>

#include "robogene/error.hpp"
#include "robogene/log.hpp"
#include "robogene/name/tcp_liveness_probe.hpp"
#include "robogene/net/tcp_listener.hpp"

namespace robogene::name {

LocalNameServer::LocalNameServer(LocalNameServerOptions options) : registry_(options.db) {
  // Bound before the service is made, so that /root is registered at the real port number.
  net::TcpListener listener = net::TcpListener::listen(options.at);
  contact_ = net::Endpoint{options.at.host, listener.local().port};
  options.service.host = contact_.host;
  options.service.port = contact_.port;
  if (options.probe_liveness) {
    probe_ = std::make_unique<TcpLivenessProbe>(options.probe_connect_timeout_ms, options.probe_answer_timeout_ms);
  }
  service_ = std::make_unique<NameService>(registry_, options.service, probe_.get());
  server_ = std::make_unique<NameServer>(*service_, std::move(listener), options.limits);
  if (options.fallback) {
    try {
      responder_ = std::make_unique<FallbackResponder>(*service_, contact_.host, options.fallback_group);
      const net::Endpoint& g = responder_->group();
      registry_.put(Registration{"fallback", "mcast", g.host, g.port, "*", 0});
    } catch (const NetworkError& e) {
      fallback_error_ = e.what();
    }
  }
  // A "fallback" entry left by an earlier run in the same database would point clients at a
  // group nobody answers.
  if (!responder_) registry_.remove("fallback");
  serving_ = std::thread([this] { server_->run(); });
  if (options.sweep_seconds > 0) {
    try {
      sweeper_ = std::thread([this, s = options.sweep_seconds, tell = std::move(options.on_dropped)] {
        sweep_until_stopped(s, tell);
      });
    } catch (...) {
      stop();  // no destructor runs for a constructor that throws
      throw;
    }
  }
}

LocalNameServer::~LocalNameServer() { stop(); }

void LocalNameServer::stop() noexcept {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_) return;
    stopping_ = true;
  }
  responder_.reset();
  server_->stop();
  if (serving_.joinable()) serving_.join();
  wake_.notify_all();
  if (sweeper_.joinable()) sweeper_.join();
}

void LocalNameServer::sweep_until_stopped(double seconds,
                                          const std::function<void(const std::string&)>& on_dropped) {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return stopping_; })) {
    lock.unlock();
    for (const auto& gone : service_->sweep()) {
      if (on_dropped) {
        on_dropped(gone);
      } else {
        log::info("/root", "dropped stale registration " + gone);
      }
    }
    lock.lock();
  }
}

}  // namespace robogene::name
