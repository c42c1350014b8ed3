// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "port_tools.hpp"

#include <cstdio>
#include <iostream>

#include "cli_support.hpp"
#include "robogene/carrier/registry.hpp"
#include "robogene/error.hpp"
#include "robogene/name_server_mcast_groups.hpp"

namespace robogene::cli {
std::string checked_port_name(const std::string& text, const std::string& what) {
  if (text.empty() || text[0] != '/' || text.find_first_of(" \t\r\n\"") != std::string::npos) {
    throw UsageError(what + " must be a port name starting with '/', got \"" + text + "\"");
  }
  return text;
}

Contact resolve(NameClient& names, const std::string& name) {
  auto c = names.query(name);
  if (!c) throw Error("port " + name + " is not registered with the name server at " + names.server().to_string());
  return *c;
}

std::unique_ptr<carrier::OutboundConnection> open_to(const Contact& port, const std::string& carrier_name,
                                                     const std::string& sender) {
  carrier::ConnectContext ctx;
  ctx.sender_name = sender;
  ctx.target_name = port.name;
  ctx.mcast_groups = name_server_mcast_groups(std::nullopt);  // the configuration's name server
  try {
    return carrier::open_connection(port.endpoint(), carrier_name, ctx);
  } catch (const Error& e) {
    throw Error("cannot reach port " + port.name + " at " + port.uri() + ": " + e.what());
  }
}

bool read_stdin_bottle(Bottle& b, std::size_t& line_number, std::size_t& errors, const char* command) {
  std::string text, line;
  std::size_t first_line = 0;
  while (std::getline(std::cin, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (text.empty()) {
      if (line.find_first_not_of(" \t") == std::string::npos) continue;  // blank lines send nothing
      first_line = line_number;
      text = line;
    } else {
      text += "\n" + line;
    }
    bool continued = !text.empty() && text.back() == '\\';
    if (continued) {
      text.pop_back();
      continue;
    }
    if (!Bottle::text_is_complete(text)) continue;
    try {
      b = Bottle::from_text(text);
      return true;
    } catch (const ParseError& e) {
      std::fprintf(stderr, "robogene %s: stdin line %zu, column %zu: %s (not sent)\n", command, first_line,
                   e.position(), e.what());
      ++errors;
      text.clear();
    }
  }
  if (!text.empty()) {
    std::fprintf(stderr, "robogene %s: stdin line %zu: input ended inside an unfinished bottle (not sent)\n", command,
                 first_line);
    ++errors;
  }
  return false;
}

}  // namespace robogene::cli
