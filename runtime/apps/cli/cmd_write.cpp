// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene write /port [/dst ...]`: opens an output port, connects it to each /dst, and sends each
// bottle typed on stdin (as `yarp write`). Ends at EOF or on SIGINT / SIGTERM, unregistering.
#include <unistd.h>

#include <cstdio>

#include "commands.hpp"
#include "port_tools.hpp"
#include "robogene/error.hpp"
#include "robogene/port.hpp"

namespace robogene::cli {

int cmd_write(Args& args) {
  net::Endpoint server = name_server_address(args);
  auto w = args.positional();
  if (w.empty()) throw UsageError("expected /port [/destination ...]");
  std::string name = checked_port_name(w[0], "the port");
  std::vector<std::string> targets;
  for (std::size_t i = 1; i < w.size(); ++i) targets.push_back(checked_port_name(w[i], "a destination"));

  Port port;
  port.open(name, NameClient(server));
  std::fprintf(stderr, "Port %s active at %s\n", name.c_str(), port.contact().uri().c_str());
  try {
    for (const auto& t : targets) {
      port.add_output(t);
      std::fprintf(stderr, "Added connection from %s to %s\n", name.c_str(), t.c_str());
    }
  } catch (...) {
    port.close();
    throw;
  }
  // stdin blocks the main thread, so a signal ends the process here once the port is closed.
  on_shutdown_signal([&port] {
    port.close();
    std::fflush(stdout);
    _exit(0);
  });
  Bottle b;
  std::size_t line = 0, errors = 0;
  while (read_stdin_bottle(b, line, errors, "write")) port.write(b);
  port.close();
  return errors ? 1 : 0;
}

}  // namespace robogene::cli
