// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Writing yarp.conf, as yarpserver does when it starts, so that programs started afterwards find
// this server (reading it is NameConfig's job).
#pragma once

#include <string>

#include "robogene/net/endpoint.hpp"

namespace robogene::cli {

// The file NameConfig::load() reads for the current namespace ($YARP_NAMESPACE, else /root).
std::string yarp_conf_path();
// Creates `path` and its parents as needed; throws robogene::Error naming the part that failed.
void ensure_directory(const std::string& path);
// Writes "HOST PORT yarp" atomically (creating the directory); throws robogene::Error naming the file.
void write_yarp_conf(const net::Endpoint& server);

}  // namespace robogene::cli
