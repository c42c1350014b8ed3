// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "payload_reader.hpp"

namespace robogene::carrier::detail {

void read_payload(net::StreamReader& in, std::size_t size, InboundMessage& m) { read_payload_from(in, size, m); }

}  // namespace robogene::carrier::detail
