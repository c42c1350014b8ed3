// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Helpers of the port commands (connect, disconnect, ping, ls, read, write, rpc): finding a port
// through the name server and talking to it the way YARP's companion tools do.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "robogene/bottle.hpp"
#include "robogene/carrier/connection.hpp"
#include "robogene/contact.hpp"
#include "robogene/name_client.hpp"

namespace robogene::cli {

// A port name as typed by the user: must start with '/'. UsageError otherwise.
std::string checked_port_name(const std::string& text, const std::string& what);

// Where `name` listens; throws robogene::Error "port /x is not registered with the name server
// at HOST:PORT" when unknown.
Contact resolve(NameClient& names, const std::string& name);

// Opens a connection to `port` with `carrier`, introducing ourselves as `sender` ("admin",
// "anon_rpc"); errors name the port and its address.
std::unique_ptr<carrier::OutboundConnection> open_to(const Contact& port, const std::string& carrier,
                                                     const std::string& sender);

// Reads stdin bottle by bottle (a bottle may span lines while quotes or brackets are open).
// Returns false at EOF. A line that does not parse is reported on stderr with its line and
// column, counted in `errors`, and skipped.
bool read_stdin_bottle(Bottle& b, std::size_t& line_number, std::size_t& errors, const char* command);

}  // namespace robogene::cli
