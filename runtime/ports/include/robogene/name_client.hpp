// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Talks to the name server the way YARP 3 clients do (reference section 4.1): one new TCP
// connection per request, raw text "NAME_SERVER query /x\n", replies as text lines ending with
// "*** end of message".
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "robogene/contact.hpp"
#include "robogene/net/endpoint.hpp"
#include "robogene/net/tcp_stream.hpp"

namespace robogene {

class NameClient {
 public:
  explicit NameClient(net::Endpoint server, net::Millis timeout = net::Millis{5000});
  // The server named by the YARP configuration (NameConfig::load()).
  static NameClient from_config();

  const net::Endpoint& server() const noexcept { return server_; }

  // nullopt when the server does not know the name.
  std::optional<Contact> query(const std::string& name);
  // Registers `name`; host/port empty/0 let the server choose ("..."). Returns what the server
  // recorded. Throws robogene::Error with the server's answer when it refuses.
  Contact register_name(const std::string& name, const std::string& carrier = "tcp",
                        const std::string& host = "", int port = 0);
  void unregister(const std::string& name);
  // `set /x key v1 v2 ...` (YARP sets offers/accepts/process after registering).
  void set_property(const std::string& name, const std::string& key,
                    const std::vector<std::string>& values);

  // Sends one raw request line and returns the reply lines (without "*** end of message").
  std::vector<std::string> request(const std::string& line);

  // Parses "registration name /w ip 127.0.0.1 port 10002 type tcp"; nullopt if not that shape.
  static std::optional<Contact> parse_registration(const std::string& line);

 private:
  net::Endpoint server_;
  net::Millis timeout_;
};

}  // namespace robogene
