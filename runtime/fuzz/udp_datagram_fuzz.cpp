// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// libFuzzer target: the datagrams a udp writer sends after its handshake, through a real UDP
// socket on 127.0.0.1 into the udp carrier's reader (datagram_fuzz_harness.hpp says how the
// input becomes datagrams and what is checked).
#include "datagram_fuzz_harness.hpp"
#include "robogene/net/udp_socket.hpp"

using namespace robogene;

namespace {

const fuzz::DatagramWire& wire() {
  static net::UdpSocket reader = net::UdpSocket::bind({"127.0.0.1", 0});
  static net::UdpSocket writer = net::UdpSocket::bind({"127.0.0.1", 0});
  static const fuzz::DatagramWire w{
      [](const std::uint8_t* d, std::size_t n) { writer.send_to(reader.local(), d, n); },
      [](void* d, std::size_t cap, net::Millis t, net::Endpoint* from) { return reader.receive(d, cap, t, from); }};
  return w;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzz::run_datagram_input(wire(), "udp", data, size);
}
