// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name/tcp_liveness_probe.hpp"

#include <memory>
#include <string>

#include "robogene/carrier/registry.hpp"
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
  auto tcp = carrier::CarrierRegistry::global().find("tcp");
  if (!tcp) throw Error("the tcp carrier is not registered");
  carrier::ConnectContext ctx;
  ctx.sender_name = "admin";  // not rooted: YARP ports do not announce such connections
  ctx.target_name = r.name;
  ctx.timeout = net::Millis{answer_timeout_ms_};
  std::unique_ptr<carrier::OutboundConnection> out;
  try {
    out = tcp->connect(std::make_unique<carrier::Link>(std::move(s)), ctx);
  } catch (const Error&) {
    // Silent, closed, or answered something else: whatever listens there is not a port.
    return Liveness::Dead;
  }
  out->close();  // the polite 'q'
  return Liveness::Alive;
}

}  // namespace robogene::name
