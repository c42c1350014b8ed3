// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// libFuzzer target: the name server as a peer reaches it, over a real loopback connection to a
// running NameServer: the carrier it picks by its first bytes (name_ser `NAME_SERVER ...`
// lines, text, text_ack, tcp, http), the /root port's commands and the name service behind
// them. Each input is one session that ends when the peer has sent everything; the server must
// answer and close it (within the handshake/idle limits), never crash or keep it.
#include <sys/socket.h>

#include <cstddef>
#include <cstdint>
#include <thread>

#include "robogene/error.hpp"
#include "robogene/log.hpp"
#include "robogene/name/name_server.hpp"
#include "robogene/name/registry.hpp"
#include "robogene/net/tcp_listener.hpp"

using namespace robogene;

namespace {

struct Server {
  name::Registry db{":memory:"};
  name::NameService service;
  name::NameServer server;
  std::thread thread;

  static name::NameServerLimits limits() {
    name::NameServerLimits l;
    l.handshake_timeout_ms = 200;
    l.idle_timeout_ms = 200;
    l.write_timeout_ms = 200;
    return l;
  }
  static net::TcpListener& bound() {
    static net::TcpListener l = net::TcpListener::listen({"127.0.0.1", 0});
    return l;
  }
  static name::NameServiceConfig config() {
    name::NameServiceConfig c;
    c.host = "127.0.0.1";
    c.port = bound().local().port;
    return c;
  }
  Server() : service(db, config(), nullptr), server(service, std::move(bound()), limits()) {
    log::set_level(log::Level::Off);
    thread = std::thread([this] { server.run(); });
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static Server* s = new Server;  // lives for the whole run: one server, many sessions
  net::TcpStream peer = net::TcpStream::connect({"127.0.0.1", s->service.config().port});
  peer.set_read_timeout(net::Millis(5000));
  try {
    peer.write_all(data, size);
  } catch (const NetworkError&) {
    return 0;  // the server refused the rest (bad header): it closed, as it should
  }
  ::shutdown(peer.fd(), SHUT_WR);
  char buf[4096];
  try {
    while (peer.read_some(buf, sizeof buf) > 0) {
    }
  } catch (const NetworkError& e) {
    // A reset is a close too; a timeout is a session the server kept: a bug.
    if (std::string(e.what()).find("timed out") != std::string::npos) __builtin_trap();
  }
  return 0;
}
