// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// How a client learns that a device server is Robogene's before it asks for the interfaces'
// fingerprints ([get] [rgif]): YARP 3's servers log every request they do not know as an error,
// so that request goes only to a server that says it can answer it. A Robogene server says so
// with a user-defined property of its request port, `robogene_service` = the service's name.
// The client reads it with the admin message [prop] [get] robogene_service, which any YARP 3
// port answers itself (an empty value for a property it lacks) without involving its device.
#pragma once

#include <string>

#include "robogene/name_client.hpp"
#include "robogene/port.hpp"

namespace robogene::dev {

inline constexpr const char* kServiceProperty = "robogene_service";

// Marks `port` as answering the requests of `service` the way Robogene's servers do.
void announce_service(Port& port, const std::string& service);

// Whether the port `name` says it serves `service` as Robogene's servers do; false for a port
// that does not say so, cannot be found or does not answer.
bool serves_robogene(NameClient& names, const std::string& name, const std::string& service);

}  // namespace robogene::dev
