// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name/tcp_liveness_probe.hpp"

#include <memory>
#include <string>
#include <vector>

#include "robogene/carrier/binary_handshake.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/error.hpp"
#include "robogene/net/tcp_stream.hpp"

namespace robogene::name {

Liveness TcpLivenessProbe::probe(const Registration& r) {
  net::TcpStream s;
  try {
    s = net::TcpStream::connect(net::Endpoint{r.host, r.port}, net::Millis{connect_timeout_ms_});
  } catch (const NetworkError& e) {
    // Only a refusal proves nobody is there; anything else may be the network's fault.
    return std::string(e.what()).find("refused") != std::string::npos ? Liveness::Dead : Liveness::Unknown;
  }
  // The tcp handshake by hand, to tell "answered, but not as a port" (a stale entry whose number
  // another program now uses) or "accepted but never answered" (a listener that is no port: every
  // port, however busy, answers from a thread of its own) from "accepted and hung up": that is
  // what a port at its limit of inputs or connections does, and a busy port is alive.
  std::uint8_t answer[8];
  std::size_t got = 0;
  bool silent = false;
  try {
    s.set_read_timeout(net::Millis{answer_timeout_ms_});
    s.set_write_timeout(net::Millis{answer_timeout_ms_});
    // "admin": not rooted, so the port does not announce the connection.
    const auto hello = carrier::binary_hello(carrier::make_yarp_number(carrier::kTcpSpecifier), "admin");
    s.write_all(hello.data(), hello.size());
    while (got < sizeof answer) {
      std::size_t n = s.read_some(answer + got, sizeof answer - got);
      if (n == 0) break;
      got += n;
    }
  } catch (const NetworkError& e) {
    // Reset: busy, not proven gone. Timed out with nothing said: no port is listening there.
    silent = got == 0 && std::string(e.what()).find("timed out") != std::string::npos;
  }
  if (got < sizeof answer) {
    const bool foreign = got >= 1 && answer[0] != 'Y';
    return foreign || silent ? Liveness::Dead : Liveness::Unknown;
  }
  if (!carrier::read_yarp_number(answer)) return Liveness::Dead;
  // A port: leave politely with 'q', as YARP's own probes do.
  auto out = carrier::tcp_outbound_after_handshake(std::make_unique<carrier::Link>(std::move(s)), true, r.name, 1024);
  out->set_timeout(net::Millis{answer_timeout_ms_});
  out->close();
  return Liveness::Alive;
}

}  // namespace robogene::name
