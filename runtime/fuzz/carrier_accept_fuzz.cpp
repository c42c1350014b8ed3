// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// libFuzzer target: the handshake and framing of every carrier, as a port's acceptor sees a
// peer's bytes on a real loopback TCP connection. The first input byte picks a carrier; the
// second says whether its handshake is sent well-formed (so the rest exercises the framing:
// tcp's index and PortCommand, the payload reader, text lines, HTTP requests) or left to the
// fuzzer. (The name server's own carriers are fuzzed by name_server_wire_fuzz.) Whatever comes, the acceptor must end in a clean error or a
// message loop that finishes; each message's bottle is decoded and answered as a port would.
#include <sys/socket.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "robogene/carrier/registry.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"
#include "robogene/net/tcp_listener.hpp"

using namespace robogene;

namespace {

// The carriers, by name, in a fixed order so that an input means the same on every run.
const std::vector<std::string>& carrier_names() {
  static const std::vector<std::string> names = [] {
    auto n = carrier::CarrierRegistry::global().names();
    std::sort(n.begin(), n.end());
    return n;
  }();
  return names;
}

// A well-formed start of a connection of `name` from the port "/fuzz".
std::vector<std::uint8_t> handshake(const std::string& name, const carrier::Carrier& c) {
  std::vector<std::uint8_t> out;
  if (name == "http") return out;  // the request line is the handshake: left to the fuzzer
  const carrier::Header h = c.header();
  out.insert(out.end(), h.begin(), h.end());
  const std::string sender = "/fuzz";
  if (c.is_text()) {
    const std::string line = sender + "\r\n";
    out.insert(out.end(), line.begin(), line.end());
  } else {
    // Binary carriers: int32 length (with the NUL), the name, the NUL (reference 3.2).
    const std::uint32_t n = static_cast<std::uint32_t>(sender.size() + 1);
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(n >> (8 * i)));
    out.insert(out.end(), sender.begin(), sender.end());
    out.push_back(0);
  }
  return out;
}

net::TcpListener& listener() {
  static net::TcpListener l = [] {
    log::set_level(log::Level::Error);
    return net::TcpListener::listen({"127.0.0.1", 0});
  }();
  return l;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const auto& names = carrier_names();
  const std::string& name = names[data[0] % names.size()];
  const auto c = carrier::CarrierRegistry::global().find(name);
  // The datagram and shared-memory carriers leave the TCP stream after the handshake: their
  // acceptors are exercised up to there (a read would wait for datagrams nobody sends).
  const bool stream_after_handshake = !c->is_connectionless() && name != "shmem";
  std::vector<std::uint8_t> bytes;
  if (data[1] & 1) {
    bytes = handshake(name, *c);
  } else {
    const carrier::Header h = c->header();
    bytes.assign(h.begin(), h.end());
  }
  bytes.insert(bytes.end(), data + 2, data + size);

  net::TcpStream client = net::TcpStream::connect(listener().local());
  auto accepted = listener().accept(net::Millis(2000));
  if (!accepted) __builtin_trap();  // our own loopback connection must arrive
  client.write_all(bytes.data(), bytes.size());
  ::shutdown(client.fd(), SHUT_WR);  // the peer has said all it will say

  carrier::AcceptContext ctx;
  ctx.local_name = "/fuzz/acceptor";
  ctx.max_message_size = 1u << 20;
  ctx.max_line_length = 1u << 16;
  ctx.handshake_timeout = net::Millis(200);
  try {
    auto conn = carrier::accept_connection(std::move(*accepted), ctx);
    if (!stream_after_handshake) return 0;
    carrier::InboundMessage m;
    DecodeLimits limits;
    limits.max_bytes = ctx.max_message_size;
    for (int n = 0; n < 64 && conn->read(m); ++n) {
      if (m.key == 'd' || m.key == 'D' || m.key == 'a') {
        try {
          const Bottle b = m.take_bottle(limits);
          if (m.reply_expected) conn->reply(b);
        } catch (const ParseError&) {
          // a malformed bottle is the port's to refuse: the connection goes on
        }
      } else if (m.key == 'r' || m.key == 'q') {
        break;
      } else {
        conn->reply_raw("?\r\n", 3);
      }
      conn->finish();
    }
  } catch (const Error&) {
    // ParseError / NetworkError naming the peer: the clean end of a bad connection
  }
  return 0;
}
