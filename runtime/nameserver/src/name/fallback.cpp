// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name/fallback.hpp"

#include <sys/uio.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "robogene/carrier/crc32.hpp"
#include "robogene/net/mcast_socket.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"

namespace robogene::name {

namespace {

using net::McastSocket;

constexpr std::size_t kPrefix = 8;     // int32 crc32(rest), int32 counter
constexpr std::size_t kMaxDatagram = 65507;
constexpr const char* kRefusedWhy =
    ": the multicast fallback answers only requests that read (query, list, get...), since a "
    "datagram's sender can be forged; send it to the name server's TCP port";

void put_int32(std::uint8_t* at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) at[i] = static_cast<std::uint8_t>(v >> (8 * i));
}

std::uint32_t get_int32(const std::uint8_t* at) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(at[i]) << (8 * i);
  return v;
}

void send_text(McastSocket& s, const net::Endpoint& group, const std::string& text) {
  std::uint8_t prefix[kPrefix];
  put_int32(prefix, carrier::crc32(text.data(), text.size()));
  put_int32(prefix + 4, 0);
  iovec parts[2] = {{prefix, kPrefix}, {const_cast<char*>(text.data()), text.size()}};
  s.send_to(group, parts, 2);
}

// The text of one datagram, or nullopt for a short one or one whose CRC does not match.
std::optional<std::string> text_of(const std::vector<std::uint8_t>& buf, std::size_t n) {
  if (n < kPrefix) return std::nullopt;
  if (get_int32(buf.data()) != carrier::crc32(buf.data() + kPrefix, n - kPrefix)) return std::nullopt;
  return std::string(reinterpret_cast<const char*>(buf.data() + kPrefix), n - kPrefix);
}

// "registration name /root ip 127.0.0.1 port 10000 type tcp" for `name_space` -> its address.
std::optional<net::Endpoint> registration_of(const std::string& text, const std::string& name_space) {
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.rfind("registration ", 0) != 0) continue;
    try {
      Bottle b = Bottle::from_text(line);
      const Value& name = b.find("name");
      if (!name.is_string() || name.as_string() != name_space) continue;
      const Value& ip = b.find("ip");
      const Value& port = b.find("port");
      if (ip.is_null() || !port.is_int()) continue;
      return net::Endpoint{ip.is_string() ? ip.as_string() : ip.to_text(), port.as_int32()};
    } catch (const ParseError&) {
      continue;  // not ours to understand: keep listening
    }
  }
  return std::nullopt;
}

}  // namespace

net::Endpoint fallback_group() {
  int port = 10000;
  if (const char* range = std::getenv("YARP_PORT_RANGE")) {
    char* end = nullptr;
    long v = std::strtol(range, &end, 10);
    if (end != range && v > 0 && v < 65536) port = static_cast<int>(v);
  }
  return {"224.2.1.1", port};
}

struct FallbackResponder::Sockets {
  McastSocket listen, send;
};

FallbackResponder::FallbackResponder(NameService& service, const std::string& iface, net::Endpoint group)
    : service_(service), group_(std::move(group)),
      sockets_(new Sockets{McastSocket::join(group_, iface), McastSocket::sender(iface)}) {
  thread_ = std::thread([this] { run(); });
}

FallbackResponder::~FallbackResponder() {
  stop_ = true;
  sockets_->listen.interrupt();
  if (thread_.joinable()) thread_.join();
}

void FallbackResponder::run() {
  std::vector<std::uint8_t> buf(kMaxDatagram);
  while (!stop_) {
    net::Endpoint from;
    std::optional<std::size_t> n;
    try {
      n = sockets_->listen.receive(buf.data(), buf.size(), net::Millis(500), &from);
    } catch (const std::exception& e) {
      log::warn("/root", std::string("fallback: ") + e.what());
      continue;
    }
    if (!n) continue;
    std::optional<std::string> text = text_of(buf, *n);
    if (!text) {
      log::warn("/root", "fallback: dropped a datagram from " + from.to_string() + " (too short or bad CRC)");
      continue;
    }
    std::string line = text->substr(0, text->find('\n'));
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.rfind("NAME_SERVER ", 0) != 0) continue;  // replies of other servers, and noise
    try {
      const Bottle request = Bottle::from_text(line);
      // Anyone on the network can send a datagram with any source address: only requests
      // that change nothing are served this way (register, unregister... need the TCP port).
      if (!NameService::is_read_only(request)) {
        log::warn("/root", "fallback: refused \"" + line + "\" from " + from.to_string() + kRefusedWhy);
        send_text(sockets_->send, group_, std::string("*** error: refused \"") + line + "\"" + kRefusedWhy + "\r\n*** end of message\r\n");
        continue;
      }
      NameReply reply = service_.apply(request, from.host);
      send_text(sockets_->send, group_, reply.to_text_wire());
    } catch (const std::exception& e) {
      log::warn("/root", "fallback: request \"" + line + "\" from " + from.to_string() + ": " + e.what());
    }
  }
}

std::optional<net::Endpoint> detect_name_server(const std::string& iface, const std::string& name_space,
                                                net::Millis timeout, net::Endpoint group) {
  McastSocket listen = McastSocket::join(group, iface);
  McastSocket send = McastSocket::sender(iface);
  std::vector<std::uint8_t> buf(kMaxDatagram);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (int attempt = 0; attempt < 3; ++attempt) {
    send_text(send, group, "NAME_SERVER query " + name_space + "\n");
    const auto until = std::min(deadline, std::chrono::steady_clock::now() + timeout / 3);
    for (;;) {
      auto left = std::chrono::duration_cast<net::Millis>(until - std::chrono::steady_clock::now());
      if (left.count() <= 0) break;
      std::optional<std::size_t> n = listen.receive(buf.data(), buf.size(), left);
      if (!n) break;
      std::optional<std::string> text = text_of(buf, *n);
      if (!text) continue;
      if (auto found = registration_of(*text, name_space)) return found;
    }
  }
  return std::nullopt;
}

}  // namespace robogene::name
