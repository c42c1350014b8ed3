// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene detect [--write]`: finds the name server with no configuration, over the multicast
// fallback (robogene/name/fallback.hpp), as `yarp detect` does; --write saves it in yarp.conf.
#include <cstdio>
#include <cstdlib>

#include "commands.hpp"
#include "robogene/error.hpp"
#include "robogene/name/fallback.hpp"
#include "yarp_conf.hpp"

namespace robogene::cli {

int cmd_detect(Args& args) {
  const bool write = args.flag("--write");
  const std::string iface = args.option("--ip").value_or("0.0.0.0");
  const double seconds = parse_seconds(args.option("--timeout").value_or("1.5"), "--timeout");
  if (!args.positional().empty()) throw UsageError("unexpected argument \"" + args.positional()[0] + "\"");
  const char* ns = std::getenv("YARP_NAMESPACE");
  const std::string name_space = ns && *ns ? ns : "/root";
  const net::Endpoint group = name::fallback_group();
  auto found = name::detect_name_server(iface, name_space, net::Millis(static_cast<long>(seconds * 1000)), group);
  if (!found) {
    throw NetworkError("no name server answered for " + name_space + " on the multicast group " + group.to_string() +
                       " (is `robogene server` or `yarpserver` running on this network, with its fallback on?)");
  }
  std::printf("%s is available at ip %s port %d\n", name_space.c_str(), found->host.c_str(), found->port);
  if (write) {
    write_yarp_conf(*found);
    std::printf("saved in %s\n", yarp_conf_path().c_str());
  }
  return 0;
}

}  // namespace robogene::cli
