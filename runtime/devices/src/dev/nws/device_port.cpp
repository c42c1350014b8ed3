// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/dev/nws/device_port.hpp"

#include <chrono>

#include "robogene/name_config.hpp"

namespace robogene::dev {

NameClient device_name_client(const Searchable& config) {
  if (!config.check("server")) return NameClient::from_config();
  const std::string text = config.get_string("server", "");
  try {
    return NameClient(NameConfig::parse_server(text));
  } catch (const Error& e) {
    throw ConfigError(config.origin("server") + ": key 'server': " + e.what());
  }
}

std::string port_name_option(const Searchable& config, std::string_view key) {
  config.require(key);
  const std::string name = config.get_string(key, "");
  if (name.size() < 2 || name[0] != '/' || name.find_first_of(" \t\r\n") != std::string::npos) {
    throw ConfigError(config.origin(key) + ": key '" + std::string(key) + "': '" + name +
                      "' is not a port name (it must start with '/' and have no spaces)");
  }
  return name;
}

double wall_time_now() {
  using namespace std::chrono;
  return duration<double>(system_clock::now().time_since_epoch()).count();
}

}  // namespace robogene::dev
