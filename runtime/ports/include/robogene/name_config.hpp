// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Where the name server is, found the YARP 3 way (reference section 4.3): the file yarp.conf
// (or <namespace>.conf with non-alphanumerics turned into '_') in $YARP_CONFIG_HOME, else
// $XDG_CONFIG_HOME/yarp, else ~/.config/yarp; the namespace from $YARP_NAMESPACE, else
// yarp_namespace.conf in the same folder, else "/root". File content "127.0.0.1 10000 yarp" or
// a [name] group with host, port and mode lines.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "robogene/net/endpoint.hpp"

namespace robogene {

struct NameConfig {
  std::string name_space = "/root";
  net::Endpoint server{"127.0.0.1", 10000};
  std::string mode = "yarp";
  std::string source;  // the file it came from, for messages

  // The configuration folder (no file access).
  static std::string config_dir();
  // The file name for a namespace: "/root" -> "yarp.conf", "/myns" -> "_myns.conf".
  static std::string file_name_for(std::string_view name_space);
  // Reads the configuration. Throws robogene::Error naming the file and line when the file
  // exists but cannot be understood, or when no file exists ("no yarp.conf in <dir>").
  static NameConfig load();
  // Parses the content of a config file; `where` names it in errors.
  static NameConfig parse(std::string_view text, const std::string& where);
  // "host:port" (the CLI's --server). Throws robogene::Error naming the text.
  static net::Endpoint parse_server(std::string_view text);
};

}  // namespace robogene
