// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene rpc /port`: sends each bottle typed on stdin as a request ('d') and prints the reply
// as `Response: ...` (as `yarp rpc`). Like `yarp rpc` it connects directly, as "anon_rpc",
// without registering a port of its own.
#include <unistd.h>

#include <cstdio>

#include "commands.hpp"
#include "port_tools.hpp"
#include "robogene/error.hpp"

namespace robogene::cli {

int cmd_rpc(Args& args) {
  NameClient names(name_server_address(args));
  std::string carrier_name = args.option("--carrier").value_or("tcp");
  auto w = args.positional();
  if (w.size() != 1) throw UsageError("expected /port");
  Contact target = resolve(names, checked_port_name(w[0], "the port"));
  auto conn = open_to(target, carrier_name, "anon_rpc");
  carrier::OutboundConnection* raw = conn.get();
  on_shutdown_signal([raw] {
    raw->close();
    std::fflush(stdout);
    _exit(0);
  });
  Bottle request, reply;
  std::size_t line = 0, errors = 0;
  while (read_stdin_bottle(request, line, errors, "rpc")) {
    carrier::OutboundMessage m;
    m.key = 'd';
    m.bottle = &request;
    try {
      conn->send(m, &reply);
    } catch (const Error& e) {
      throw Error("port " + target.name + " at " + target.uri() + " failed during the request on stdin line " +
                  std::to_string(line) + ": " + e.what());
    }
    std::printf("Response: %s\n", reply.to_text().c_str());
    std::fflush(stdout);
  }
  conn->close();
  return errors ? 1 : 0;
}

}  // namespace robogene::cli
