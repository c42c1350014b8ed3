// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The handshake every binary carrier (tcp, fast_tcp, udp, mcast, shmem) starts with, written
// once (reference section 3.2): the initiator sends its carrier's 8-byte header and its name as
// int32 LE (length + 1), the name, a NUL, plus whatever its carrier adds (mcast: the group);
// the acceptor reads the name and answers `YA <n> RP` (tcp: its port number, udp: the udp port,
// shmem: the length of the segment name that follows).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "robogene/carrier/connection.hpp"
#include "robogene/carrier/yarp_number.hpp"

namespace robogene::carrier {

// The initiator's first bytes: `header`, the sender name, then `extra`.
std::vector<std::uint8_t> binary_hello(const Header& header, const std::string& sender_name,
                                       const std::vector<std::uint8_t>& extra = {});
// Sends binary_hello(...) in one write.
void send_binary_hello(Link& link, const Header& header, const std::string& sender_name,
                       const std::vector<std::uint8_t>& extra = {});
// Reads the acceptor's 8-byte answer `YA <n> RP` and returns n. Anything else throws
// NetworkError "<where>: expected <expected>, got <the 8 bytes in hex>".
std::int32_t read_binary_answer(Link& link, const std::string& where, const std::string& expected);

// Acceptor: reads and checks the sender name (length 1..max_length, NUL dropped); qualifiers
// YARP may append after a space ("/w (log.in 1)") are dropped from the returned port name.
// A length out of range throws ParseError naming the peer and byte offset 8.
std::string read_binary_sender_name(Link& link, std::size_t max_length);
// Acceptor: answers `YA <n> RP`.
void send_binary_answer(Link& link, std::int32_t n);

// The tcp connection of an initiator that made the handshake itself (the name server's
// liveness probe, which must tell how a peer fails): messages, acks and the polite close.
std::unique_ptr<OutboundConnection> tcp_outbound_after_handshake(std::unique_ptr<Link> link, bool acks,
                                                                 const std::string& target,
                                                                 std::size_t max_reply_size);

}  // namespace robogene::carrier
