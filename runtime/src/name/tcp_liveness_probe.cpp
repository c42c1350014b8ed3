// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name/tcp_liveness_probe.hpp"

#include <string>

#include "robogene/error.hpp"
#include "robogene/net/tcp_stream.hpp"
#include "yarp_wire.hpp"

namespace robogene::name {

Liveness TcpLivenessProbe::probe(const Registration& r) {
  net::TcpStream s;
  try {
    s = net::TcpStream::connect(net::Endpoint{r.host, r.port}, net::Millis{connect_timeout_ms_});
  } catch (const NetworkError& e) {
    // Only a refusal proves nobody is there; anything else may be the network's fault.
    return std::string(e.what()).find("refused") != std::string::npos ? Liveness::Dead : Liveness::Unknown;
  }
  bool answered = false;
  try {
    s.set_read_timeout(net::Millis{answer_timeout_ms_});
    s.set_write_timeout(net::Millis{answer_timeout_ms_});
    std::vector<std::uint8_t> hello;
    wire::Header h = wire::yarp_number(wire::kTcpSpecifier);
    hello.insert(hello.end(), h.begin(), h.end());
    const std::string sender = "admin";
    wire::put_le32(hello, static_cast<std::int32_t>(sender.size() + 1));
    hello.insert(hello.end(), sender.begin(), sender.end());
    hello.push_back(0);
    s.write_all(hello.data(), hello.size());
    wire::Header answer;
    s.read_exact(answer.data(), answer.size());
    if (!wire::read_yarp_number(answer)) return Liveness::Dead;  // something else owns that number now
    answered = true;
    auto bye = wire::indexed_message({wire::port_command_string("q")});
    s.write_all(bye.data(), bye.size());
    wire::Header ack;
    s.read_exact(ack.data(), ack.size());  // best effort: a port that closes at once is alive too
  } catch (const NetworkError&) {
    // Silent or closed before answering the header: whatever listens there is not a port.
    // After the answer, a port that hangs up without acking our 'q' is still a port.
    if (!answered) return Liveness::Dead;
  }
  return Liveness::Alive;
}

}  // namespace robogene::name
