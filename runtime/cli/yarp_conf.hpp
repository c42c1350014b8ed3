// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// yarp.conf, where YARP 3 programs find the name server (reference section 4.3): in
// $YARP_CONFIG_HOME, else $XDG_CONFIG_HOME/yarp, else ~/.config/yarp; `<safe namespace>.conf`
// when $YARP_NAMESPACE names another namespace than /root. Content "HOST PORT yarp" or a
// [name] section with host/port.
#pragma once

#include <optional>
#include <string>

#include "robogene/net/endpoint.hpp"

namespace robogene::cli {

std::string yarp_config_dir();
std::string yarp_conf_path();
// The server address in the file; nullopt when there is no file. Throws robogene::Error naming
// the file and line when it exists but cannot be understood.
std::optional<net::Endpoint> read_yarp_conf();
// Creates `path` and its parents as needed; throws robogene::Error naming the part that failed.
void ensure_directory(const std::string& path);
// Writes "HOST PORT yarp" (creating the directory); throws robogene::Error naming the file.
void write_yarp_conf(const net::Endpoint& server);

}  // namespace robogene::cli
