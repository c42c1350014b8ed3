// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Factories for the carriers every port speaks (the registry starts with these).
#pragma once

#include <memory>

#include "robogene/carrier/carrier.hpp"

namespace robogene::carrier {

// tcp (`YA e4 1e 00 00 RP`, acks every message) or fast_tcp (`YA 64 1e...`, no acks).
std::shared_ptr<const Carrier> make_tcp_carrier(bool with_acks);
// text (`CONNECT `) or text_ack (`CONNACK `, "<ACK>" after every message).
std::shared_ptr<const Carrier> make_text_carrier(bool with_acks);
// udp (`YA 61 1e...`): handshake over tcp, then CRC-framed datagrams (reference section 3.6).
std::shared_ptr<const Carrier> make_udp_carrier();

}  // namespace robogene::carrier
