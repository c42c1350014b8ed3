// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// How a connectionless output (udp, mcast) ends its reader's input: no quit message can travel
// on the data path, so, as YARP's NetworkBase::disconnectInput does, the writer opens a text_ack
// connection to the reader as "admin" and sends `[del] "<sender>"` (private to src/carrier).
#pragma once

#include <string>

#include "robogene/net/endpoint.hpp"

namespace robogene::carrier::detail {

// Best effort within one second: a reader that is gone already needs nothing. Failures are
// logged at debug level only.
void close_input_out_of_band(const net::Endpoint& reader, const std::string& reader_name,
                             const std::string& sender) noexcept;

}  // namespace robogene::carrier::detail
