// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// One-shot operations on other ports, the way YARP's tools do them (reference section 3.4):
// `yarp connect /a /b` = a text_ack connection to /a from "admin" carrying [add] "tcp://b";
// `yarp disconnect` = [del]; `yarp rpc` = an anonymous 'd' message.
#pragma once

#include <string>

#include "robogene/bottle.hpp"
#include "robogene/contact.hpp"
#include "robogene/name_client.hpp"
#include "robogene/net/tcp_stream.hpp"

namespace robogene::network {

struct AdminResult {
  bool ok = false;
  std::string message;  // the port's report, e.g. "Added connection from /a to tcp://b"
};

// Sends one admin Bottle to `port` over text_ack (sender "admin") and returns its reply.
Bottle admin(const Contact& port, const Bottle& request, net::Millis timeout = net::Millis{5000});

// Asks `source` to send its output to `target` ("/b"; `carrier` empty = tcp).
AdminResult connect(NameClient& names, const std::string& source, const std::string& target,
                    const std::string& carrier = "");
AdminResult disconnect(NameClient& names, const std::string& source, const std::string& target);

// Sends `request` to `port` as an anonymous sender and returns the reply (`yarp rpc`).
Bottle rpc(const Contact& port, const Bottle& request, const std::string& carrier = "tcp",
           const std::string& sender = "anon_rpc", net::Millis timeout = net::Millis{5000});

}  // namespace robogene::network
