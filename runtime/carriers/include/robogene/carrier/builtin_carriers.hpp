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
// mcast (`YA 62 1e...`): tcp handshake naming a multicast group, then datagrams to the group.
std::shared_ptr<const Carrier> make_mcast_carrier();
// shmem (`YA 6f 1e...`): same-host shared-memory rings after a tcp handshake.
std::shared_ptr<const Carrier> make_shmem_carrier();
// http (`GET /...`, `POST /fo`): a web browser reaching a port; accept only.
std::shared_ptr<const Carrier> make_http_carrier();

}  // namespace robogene::carrier
