// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The binary sender name of the handshake: int32 LE (length + 1), the name, a NUL.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "robogene/carrier/connection.hpp"

namespace robogene::carrier::detail {

void append_binary_sender_name(std::vector<std::uint8_t>& out, const std::string& name);
// Reads and validates a sender name (length 1..max_length, NUL dropped); qualifiers YARP may
// append after a space ("/w (log.in 1)") are dropped from the returned port name.
std::string read_binary_sender_name(Link& link, std::size_t max_length);

}  // namespace robogene::carrier::detail
