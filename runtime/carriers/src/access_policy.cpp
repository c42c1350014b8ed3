// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/access_policy.hpp"

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <netinet/in.h>

#include <cstdlib>
#include <cstring>

#include "robogene/error.hpp"

namespace robogene {

namespace {

std::vector<std::string> entries_of(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : text) {
    if (c == ',' || c == ' ' || c == '\t') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

// An IPv4 peer, also when the socket reported it IPv4-mapped ("::ffff:10.0.0.7").
bool ipv4_of(const std::string& host, std::uint32_t& out) {
  std::string h = host;
  if (h.rfind("::ffff:", 0) == 0) h = h.substr(7);
  in_addr a{};
  if (inet_pton(AF_INET, h.c_str(), &a) != 1) return false;
  out = ntohl(a.s_addr);
  return true;
}

bool own_interface_address(const std::string& host) {
  std::uint32_t v4 = 0;
  const bool is_v4 = ipv4_of(host, v4);
  in6_addr v6{};
  const bool is_v6 = !is_v4 && inet_pton(AF_INET6, host.c_str(), &v6) == 1;
  if (!is_v4 && !is_v6) return false;
  ifaddrs* list = nullptr;
  if (getifaddrs(&list) != 0) return false;
  bool found = false;
  for (ifaddrs* i = list; i && !found; i = i->ifa_next) {
    if (!i->ifa_addr) continue;
    if (is_v4 && i->ifa_addr->sa_family == AF_INET) {
      found = ntohl(reinterpret_cast<sockaddr_in*>(i->ifa_addr)->sin_addr.s_addr) == v4;
    } else if (is_v6 && i->ifa_addr->sa_family == AF_INET6) {
      found = std::memcmp(&reinterpret_cast<sockaddr_in6*>(i->ifa_addr)->sin6_addr, &v6, sizeof v6) == 0;
    }
  }
  freeifaddrs(list);
  return found;
}

}  // namespace

AccessPolicy::AccessPolicy() = default;

AccessPolicy AccessPolicy::parse(const std::string& allow, const std::string& source) {
  AccessPolicy p;
  p.local_ = false;
  for (const std::string& e : entries_of(allow)) {
    if (e == "local") {
      p.local_ = true;
    } else if (e == "any") {
      p.any_ = true;
    } else if (e == "none") {
      // allows nobody; combined with other entries it adds nothing
    } else {
      const std::size_t slash = e.find('/');
      Network n;
      if (!ipv4_of(e.substr(0, slash), n.address) || e.rfind("::ffff:", 0) == 0) {
        throw Error(source + ": \"" + e + "\" is not local, any, none, an IPv4 address or an IPv4 network a.b.c.d/n");
      }
      if (slash != std::string::npos) {
        const std::string bits = e.substr(slash + 1);
        char* end = nullptr;
        const long v = std::strtol(bits.c_str(), &end, 10);
        if (bits.empty() || *end != '\0' || v < 0 || v > 32) {
          throw Error(source + ": \"" + e + "\" has a prefix length that is not 0..32");
        }
        n.prefix = static_cast<int>(v);
      }
      p.networks_.push_back(n);
    }
  }
  return p;
}

AccessPolicy AccessPolicy::from_environment() {
  const char* allow = std::getenv("ROBOGENE_ALLOW");
  AccessPolicy p = allow ? parse(allow, "ROBOGENE_ALLOW") : AccessPolicy();
  if (const char* writes = std::getenv("ROBOGENE_HTTP_WRITES")) {
    const std::string w = writes;
    if (w == "1") {
      p.http_writes_ = true;
    } else if (w != "0" && !w.empty()) {
      throw Error("ROBOGENE_HTTP_WRITES: \"" + w + "\" is not 0 or 1");
    }
  }
  return p;
}

bool AccessPolicy::allows(const std::string& host) const {
  if (any_) return true;
  std::uint32_t v4 = 0;
  if (ipv4_of(host, v4)) {
    for (const Network& n : networks_) {
      const std::uint32_t mask = n.prefix == 0 ? 0 : ~std::uint32_t{0} << (32 - n.prefix);
      if ((v4 & mask) == (n.address & mask)) return true;
    }
  }
  return local_ && is_local_address(host);
}

std::string AccessPolicy::describe() const {
  std::string out;
  auto add = [&out](const std::string& s) { out += (out.empty() ? "" : " ") + s; };
  if (any_) add("any");
  if (local_) add("local");
  for (const Network& n : networks_) {
    in_addr a{};
    a.s_addr = htonl(n.address);
    char text[INET_ADDRSTRLEN] = {};
    inet_ntop(AF_INET, &a, text, sizeof text);
    add(std::string(text) + "/" + std::to_string(n.prefix));
  }
  return out.empty() ? "none" : out;
}

bool is_local_address(const std::string& host) {
  std::uint32_t v4 = 0;
  if (ipv4_of(host, v4) && (v4 >> 24) == 127) return true;
  if (host == "::1") return true;
  return own_interface_address(host);
}

std::string refusal_text(const std::string& what, const std::string& peer_host) {
  return what + " refused: peer " + peer_host +
         " is not on this process's allow-list (set ROBOGENE_ALLOW to open it; see docs/security.md)";
}

}  // namespace robogene
