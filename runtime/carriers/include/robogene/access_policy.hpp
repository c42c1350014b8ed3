// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Who may do what (docs/security.md). Reading data, describing a port and asking the name server
// are open to every peer, as in YARP. Control — connecting or disconnecting a port ([add],
// [del], "/port", "!port", "~port"), setting port properties and the scheduling of threads
// ([prop] [set]), and any write over HTTP — is refused unless the peer's address is on the
// allow-list, which by default holds only "local": this host's own addresses (127.0.0.0/8, ::1,
// and the address of every interface of this machine).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace robogene {

class AccessPolicy {
 public:
  // The default policy: local peers only, HTTP writes off.
  AccessPolicy();

  // Parses an allow-list: entries separated by commas or spaces, each "local", "any", an IPv4
  // address ("10.0.0.7") or an IPv4 network ("10.0.0.0/24"); "" or "none" allows nobody.
  // Throws robogene::Error naming `source` (the variable or option it came from) and the entry.
  static AccessPolicy parse(const std::string& allow, const std::string& source = "allow-list");

  // $ROBOGENE_ALLOW (default "local") and $ROBOGENE_HTTP_WRITES ("1" enables HTTP writes from
  // allowed peers; default off). Throws robogene::Error naming the variable on a bad value.
  static AccessPolicy from_environment();

  // Whether a peer at `host` (dotted quad or IPv6 text, as the socket reported it) may control.
  bool allows(const std::string& host) const;

  // HTTP requests that deliver data or admin messages to a port ("GET /?data=..."): a browser
  // sends them for any page that links to the port, so they are refused unless enabled here
  // (and then still only from allowed peers).
  bool http_writes() const noexcept { return http_writes_; }
  AccessPolicy& set_http_writes(bool on) noexcept {
    http_writes_ = on;
    return *this;
  }

  // The allow-list as parse() reads it back ("local", "10.0.0.0/24 127.0.0.1/32").
  std::string describe() const;

 private:
  struct Network {
    std::uint32_t address = 0;  // host byte order
    int prefix = 32;
  };
  bool any_ = false;
  bool local_ = true;
  std::vector<Network> networks_;
  bool http_writes_ = false;
};

// Whether `host` is an address of this machine: loopback (127.0.0.0/8, ::1, also IPv4-mapped)
// or the address of one of its interfaces right now.
bool is_local_address(const std::string& host);

// The reply text of a refusal, naming the peer, what it asked, and the setting that opens it.
std::string refusal_text(const std::string& what, const std::string& peer_host);

}  // namespace robogene
