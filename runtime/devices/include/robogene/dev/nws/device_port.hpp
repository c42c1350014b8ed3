// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// What the network wrappers share: reading port names from a device configuration and opening
// ports with the name server it names (`server HOST:PORT`, as `robogene dev --server` passes
// it), else the one of the YARP configuration (yarp.conf).
#pragma once

#include <string>
#include <string_view>

#include "robogene/dev/property.hpp"
#include "robogene/name_client.hpp"
#include "robogene/port.hpp"

namespace robogene::dev {

// The name server for the ports of a device opened with `config`.
NameClient device_name_client(const Searchable& config);

// The port name under `key`: required, starts with '/', has no spaces. ConfigError otherwise,
// naming where the key was set.
std::string port_name_option(const Searchable& config, std::string_view key);

// Seconds since the epoch, as YARP's Time::now() stamps messages.
double wall_time_now();

}  // namespace robogene::dev
