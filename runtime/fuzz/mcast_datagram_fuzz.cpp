// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// libFuzzer target: the datagrams an mcast writer sends to its group, through real multicast
// sockets on 127.0.0.1 (the reader joined as the mcast acceptor joins) into the mcast carrier's
// reader (datagram_fuzz_harness.hpp says how the input becomes datagrams and what is checked).
// The group and port come from the process id, so that parallel runs do not hear each other.
#include <unistd.h>

#include "robogene/net/mcast_socket.hpp"
#include "datagram_fuzz_harness.hpp"

using namespace robogene;

namespace {

net::Endpoint group() {
  const unsigned pid = static_cast<unsigned>(::getpid());
  return {"239.255." + std::to_string((pid >> 8) & 255) + "." + std::to_string(pid & 255),
          static_cast<int>(20000 + pid % 20000)};
}

const fuzz::DatagramWire& wire() {
  static const net::Endpoint to = group();
  static net::McastSocket reader = net::McastSocket::join(to, "127.0.0.1");
  static net::McastSocket writer = net::McastSocket::sender("127.0.0.1");
  static const fuzz::DatagramWire w{
      [](const std::uint8_t* d, std::size_t n) {
        iovec v{const_cast<std::uint8_t*>(d), n};
        writer.send_to(to, &v, 1);
      },
      [](void* d, std::size_t cap, net::Millis t, net::Endpoint* from) { return reader.receive(d, cap, t, from); }};
  return w;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzz::run_datagram_input(wire(), "mcast", data, size);
}
