// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Message framing shared by the binary carriers (tcp, fast_tcp, udp): the index
// `YA 0a 00 00 00 RP, nIn, nOut, ff x8, lengths` then PortCommand and payload (reference 3.3).
#pragma once

#include <sys/uio.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "robogene/carrier/encoded_payload.hpp"
#include "robogene/carrier/message.hpp"
#include "robogene/carrier/port_command.hpp"

namespace robogene::carrier::detail {

// Fills `head` with index + PortCommand and `iov` with head followed by the payload blocks, the
// whole message in one gather list. `payload` may be null (r, q).
void frame_message(const OutboundMessage& m, const EncodedPayload* payload,
                   std::vector<std::uint8_t>& head, std::vector<iovec>& iov);

// Reads the rest of a message whose first 8 bytes (`first8`) were read already, from any
// source that can read exact byte counts; `read_payload(n, m)` fills m's payload with the last
// n bytes. Throws ParseError / NetworkError naming `peer`.
template <typename ReadExact, typename ReadPayload>
void read_message_after_first8(const std::uint8_t* first8, ReadExact&& read_exact,
                               ReadPayload&& read_payload, InboundMessage& m, std::size_t max_size,
                               const std::string& peer);

// Ack `YA 00 00 00 00 RP`.
extern const std::uint8_t kAck[8];

std::string hex_bytes(const std::uint8_t* data, std::size_t n);

}  // namespace robogene::carrier::detail

#include "binary_framing_read.ipp"
