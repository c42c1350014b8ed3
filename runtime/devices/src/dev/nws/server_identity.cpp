// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/dev/nws/server_identity.hpp"

#include <exception>

#include "robogene/network.hpp"

namespace robogene::dev {

void announce_service(Port& port, const std::string& service) {
  port.set_property(kServiceProperty, Value(service));
}

bool serves_robogene(NameClient& names, const std::string& name, const std::string& service) {
  try {
    const auto contact = names.query(name);
    if (!contact) return false;
    const Bottle reply =
        network::admin(*contact, Bottle{Value::vocab("prop"), Value::vocab("get"), Value(kServiceProperty)});
    return reply.size() == 1 && reply[0].is_string() && reply[0].as_string() == service;
  } catch (const std::exception&) {
    return false;  // a port that cannot be asked is not known to be Robogene's
  }
}

}  // namespace robogene::dev
