// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Request/reply on top of Port ('d' messages, raw reply then ack, reference 3.3): RpcClient
// talks to one server; RpcServer answers each request with a handler or through read()/reply().
#pragma once

#include <functional>
#include <string>

#include "robogene/port.hpp"

namespace robogene {

class RpcClient {
 public:
  explicit RpcClient(PortOptions options = {}) : port_(options) {}
  Port& port() noexcept { return port_; }
  void open(const std::string& name) { port_.open(name); }
  void open(const std::string& name, NameClient names) { port_.open(name, std::move(names)); }
  void open_at(const std::string& name, const net::Endpoint& at) { port_.open_at(name, at); }
  // Connects to the server port (replacing any previous server).
  void connect(const std::string& server, const std::string& carrier = "tcp");
  void connect(const Contact& server);
  // Sends `request` and waits for the reply. Throws NetworkError naming the server when there
  // is no connection or it failed.
  Bottle call(const Bottle& request);
  void close() { port_.close(); }

 private:
  Port port_;
  std::string server_;
};

class RpcServer {
 public:
  using Handler = std::function<Bottle(const Bottle& request, const MessageInfo& info)>;

  explicit RpcServer(PortOptions options = {}) : port_(options) {}
  Port& port() noexcept { return port_; }
  void open(const std::string& name) { port_.open(name); }
  void open(const std::string& name, NameClient names) { port_.open(name, std::move(names)); }
  void open_at(const std::string& name, const net::Endpoint& at) { port_.open_at(name, at); }
  // Answers every request on its connection's thread.
  void serve(Handler h);
  // Or: take requests one by one and reply() to each.
  bool read(Bottle& request, net::Millis timeout = net::kNoTimeout, MessageInfo* info = nullptr) {
    return port_.read(request, true, timeout, info);
  }
  void reply(const Bottle& b) { port_.reply(b); }
  void close() { port_.close(); }

 private:
  Port port_;
};

}  // namespace robogene
