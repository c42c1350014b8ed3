// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene ls`: every registered port, with its connections and their carriers, asked of each
// port through the administrative [list] [out] / [list] [in] requests.
#include <cstdio>

#include "commands.hpp"
#include "port_tools.hpp"
#include "robogene/error.hpp"
#include "robogene/network.hpp"

namespace robogene::cli {
namespace {

// "(from "/w") (to "/r") (carrier tcp)" -> "tcp"
std::string carrier_of(const Bottle& route) {
  const Bottle* c = route.find_group("carrier");
  return c && c->size() > 1 ? c->get(1).to_text() : "?";
}

void show_direction(const Contact& port, const char* dir, const char* arrow) {
  Bottle names = network::admin(port, Bottle{Value::vocab("list"), Value::vocab(dir)});
  for (const auto& v : names) {
    // Only port-to-port connections: tools (our own "admin" query included) have unrooted names.
    if (!v.is_string() || v.as_string().empty() || v.as_string()[0] != '/') continue;
    Bottle route = network::admin(port, Bottle{Value::vocab("list"), Value::vocab(dir), v});
    std::printf("  %s %s (%s)\n", arrow, v.as_string().c_str(), carrier_of(route).c_str());
  }
}

}  // namespace

int cmd_ls(Args& args) {
  NameClient names(name_server_address(args));
  auto w = args.positional();
  if (w.size() > 1) throw UsageError("expected at most one prefix");
  std::string request = "NAME_SERVER list" + (w.empty() ? std::string() : " " + w[0]) + "\n";
  for (const auto& line : names.request(request)) {
    auto port = NameClient::parse_registration(line);
    if (!port) continue;
    std::printf("%s  %s\n", port->name.c_str(), port->uri().c_str());
    try {
      show_direction(*port, "out", "->");
      show_direction(*port, "in", "<-");
    } catch (const Error& e) {
      std::printf("  (not answering: %s)\n", e.what());
    }
  }
  std::fflush(stdout);
  return 0;
}

}  // namespace robogene::cli
