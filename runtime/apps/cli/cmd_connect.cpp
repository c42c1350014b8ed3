// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene connect /a /b [carrier]` and `robogene disconnect /a /b`: done the YARP way, by asking
// the source port over text_ack ([add] / [del]), so they work on real YARP ports too.
#include <cstdio>

#include "commands.hpp"
#include "port_tools.hpp"
#include "robogene/error.hpp"
#include "robogene/network.hpp"

namespace robogene::cli {
namespace {

int report(const network::AdminResult& r, const std::string& what) {
  if (!r.ok) throw Error(what + " failed: " + r.message);
  std::printf("Success: %s\n", r.message.c_str());
  return 0;
}

}  // namespace

int cmd_connect(Args& args) {
  NameClient names(name_server_address(args));
  auto w = args.positional();
  if (w.size() < 2 || w.size() > 3) throw UsageError("expected /from /to [carrier]");
  std::string from = checked_port_name(w[0], "the source");
  std::string to = checked_port_name(w[1], "the destination");
  return report(network::connect(names, from, to, w.size() == 3 ? w[2] : ""), "connecting " + from + " to " + to);
}

int cmd_disconnect(Args& args) {
  NameClient names(name_server_address(args));
  auto w = args.positional();
  if (w.size() != 2) throw UsageError("expected /from /to");
  std::string from = checked_port_name(w[0], "the source");
  std::string to = checked_port_name(w[1], "the destination");
  return report(network::disconnect(names, from, to), "disconnecting " + from + " from " + to);
}

}  // namespace robogene::cli
