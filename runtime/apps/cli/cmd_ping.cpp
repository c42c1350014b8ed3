// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene ping /port`: is the port there and answering? Asks it [ver] over tcp as "admin".
#include <chrono>
#include <cstdio>

#include "commands.hpp"
#include "port_tools.hpp"
#include "robogene/error.hpp"

namespace robogene::cli {

int cmd_ping(Args& args) {
  NameClient names(name_server_address(args));
  auto w = args.positional();
  if (w.size() != 1) throw UsageError("expected /port");
  Contact port = resolve(names, checked_port_name(w[0], "the port"));
  auto start = std::chrono::steady_clock::now();
  auto conn = open_to(port, "tcp", "admin");
  Bottle request{Value::vocab("ver")}, reply;
  carrier::OutboundMessage m;
  m.key = 'a';
  m.bottle = &request;
  try {
    conn->send(m, &reply);
  } catch (const Error& e) {
    throw Error("port " + port.name + " at " + port.uri() + " accepted a connection but did not answer [ver]: " +
                e.what());
  }
  double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  conn->close();
  std::printf("Port %s is alive at %s (answered %s in %.2f ms)\n", port.name.c_str(), port.uri().c_str(),
              reply.to_text().c_str(), ms);
  return 0;
}

}  // namespace robogene::cli
