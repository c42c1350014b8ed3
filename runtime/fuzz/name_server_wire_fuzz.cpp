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

#include "robogene/error.hpp"
#include "robogene/log.hpp"
#include "robogene/name/local_name_server.hpp"
#include "robogene/net/tcp_stream.hpp"

using namespace robogene;

namespace {

name::LocalNameServer* start_server() {
  log::set_level(log::Level::Off);
  name::LocalNameServerOptions o;
  o.limits.handshake_timeout_ms = 200;
  o.limits.idle_timeout_ms = 200;
  o.limits.write_timeout_ms = 200;
  return new name::LocalNameServer(o);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static name::LocalNameServer* s = start_server();  // lives for the whole run: one server, many sessions
  net::TcpStream peer = net::TcpStream::connect(s->contact());
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
