// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Reads a message payload of known length. Large payloads are walked as a Bottle encoding while
// they arrive, so that big blob bodies (image pixels) land directly in their own buffers
// (InboundMessage::detached_blobs) instead of being copied out of the payload later. Whatever
// does not look like a Bottle is read as plain bytes: the stream stays in step either way.
#pragma once

#include <cstddef>

#include "robogene/carrier/message.hpp"
#include "robogene/net/stream_reader.hpp"

namespace robogene::carrier::detail {

constexpr std::size_t kDetachBlobsFrom = 64 * 1024;

void read_payload(net::StreamReader& in, std::size_t size, InboundMessage& m);
// The same from any source with read_exact(void*, size_t).
template <typename In>
void read_payload_from(In& in, std::size_t size, InboundMessage& m);

}  // namespace robogene::carrier::detail

#include "payload_reader.ipp"
