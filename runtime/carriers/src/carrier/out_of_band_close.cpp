// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "out_of_band_close.hpp"

#include "robogene/carrier/registry.hpp"
#include "robogene/log.hpp"

namespace robogene::carrier::detail {

void close_input_out_of_band(const net::Endpoint& reader, const std::string& reader_name,
                             const std::string& sender) noexcept {
  if (sender.empty() || sender[0] != '/') return;  // anonymous senders cannot be named in [del]
  try {
    ConnectContext ctx;
    ctx.sender_name = "admin";
    ctx.target_name = reader_name;
    ctx.timeout = net::Millis{1000};
    auto conn = open_connection(reader, "text_ack", ctx);
    Bottle del{Value::vocab("del"), Value(sender)};
    OutboundMessage m;
    m.key = 'a';
    m.bottle = &del;
    Bottle reply;
    conn->send(m, &reply);
    conn->interrupt();
  } catch (const std::exception& e) {
    log::debug(sender, "could not ask " + reader_name + " at " + reader.to_string() +
                           " to drop its input: " + e.what());
  }
}

}  // namespace robogene::carrier::detail
