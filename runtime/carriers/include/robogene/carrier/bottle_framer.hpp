// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Reads exactly one binary Bottle from a stream whose length is not announced (a raw reply on
// tcp has no index): walks tags and lengths as they arrive, bounded by DecodeLimits.
#pragma once

#include <cstdint>
#include <vector>

#include "robogene/bottle.hpp"
#include "robogene/limits.hpp"
#include "robogene/net/stream_reader.hpp"

namespace robogene::carrier {

// Appends the bytes of one encoded bottle to `out`. If `first8` is given, those 8 bytes were
// already read from the stream and start the bottle. Throws ParseError (offset within the
// bottle) for impossible tags or sizes, NetworkError when the stream ends. `budget` (may be
// null) counts the bytes in the process's bytes-in-transit total as they arrive, and throws
// NetworkError when that total would pass its limit.
void read_bottle_bytes(net::StreamReader& in, std::vector<std::uint8_t>& out,
                       const DecodeLimits& limits, const std::uint8_t* first8 = nullptr,
                       ReceivingBytes* budget = nullptr);

}  // namespace robogene::carrier
