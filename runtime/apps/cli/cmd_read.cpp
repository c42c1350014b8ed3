// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene read /port [/src]`: opens an input port and prints every bottle it receives in text
// form, one per line (as `yarp read`). Stops on SIGINT / SIGTERM, unregistering the port.
#include <cstdio>
#include <mutex>

#include "commands.hpp"
#include "port_tools.hpp"
#include "robogene/error.hpp"
#include "robogene/network.hpp"
#include "robogene/port.hpp"

namespace robogene::cli {

int cmd_read(Args& args) {
  net::Endpoint server = name_server_address(args);
  bool show_envelope = args.flag("--envelope");
  PortOptions options;
  if (auto m = args.option("--max-message")) options.max_message_size = parse_bytes(*m, "--max-message");
  auto w = args.positional();
  if (w.empty() || w.size() > 2) throw UsageError("expected /port [/source]");
  std::string name = checked_port_name(w[0], "the port");
  std::string source = w.size() == 2 ? checked_port_name(w[1], "the source") : "";

  std::mutex print_mutex;
  Port port(options);
  port.set_reader([&](const Bottle& data, const MessageInfo& info, Bottle*) {
    std::string line = data.to_text();
    std::lock_guard<std::mutex> lock(print_mutex);
    if (show_envelope && !info.envelope.empty()) std::printf("%s | ", info.envelope.c_str());
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  });
  NameClient names(server);
  port.open(name, names);
  std::fprintf(stderr, "Port %s active at %s\n", name.c_str(), port.contact().uri().c_str());

  if (!source.empty()) {
    try {
      auto r = network::connect(names, source, name);
      if (!r.ok) throw Error("connecting " + source + " to " + name + " failed: " + r.message);
      std::fprintf(stderr, "Success: %s\n", r.message.c_str());
    } catch (...) {
      port.close();
      throw;
    }
  }
  wait_for_shutdown_signal();
  port.close();
  return 0;
}

}  // namespace robogene::cli
