// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Template body of read_message_after_first8 (included by binary_framing.hpp).
#pragma once

#include "grow_read.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/error.hpp"

namespace robogene::carrier::detail {

template <typename ReadExact, typename ReadPayload>
void read_message_after_first8(const std::uint8_t* first8, ReadExact&& read_exact,
                               ReadPayload&& read_payload, InboundMessage& m, std::size_t max_size,
                               const std::string& peer) {
  auto n = read_yarp_number(first8);
  if (!n || *n != kIndexLength) {
    throw ParseError(0, "message from " + peer + ": expected index header YA 0a 00 00 00 RP at "
                        "byte offset 0, got " + hex_bytes(first8, 8));
  }
  std::uint8_t counts[10];
  read_exact(counts, 10);
  std::size_t n_in = counts[0], n_out = counts[1];
  std::vector<std::uint8_t> lengths((n_in + n_out) * 4);
  if (!lengths.empty()) read_exact(lengths.data(), lengths.size());
  std::uint64_t total = 0;
  for (std::size_t i = 0; i < n_in + n_out; ++i) {
    std::int32_t len = get_int32(lengths.data() + 4 * i);
    if (len < 0) {
      throw ParseError(18 + 4 * i, "message from " + peer + ": negative block length " +
                                       std::to_string(len) + " at byte offset " +
                                       std::to_string(18 + 4 * i));
    }
    total += static_cast<std::uint64_t>(len);
  }
  if (total > max_size) {
    throw ParseError(18, "message from " + peer + " announces " + std::to_string(total) +
                             " bytes, more than the maximum message size of " +
                             std::to_string(max_size));
  }
  std::size_t body_offset = 18 + lengths.size();
  if (total < 8) {
    throw ParseError(body_offset, "message from " + peer + " has " + std::to_string(total) +
                                      " bytes, too short for the 8-byte PortCommand");
  }
  std::uint8_t cmd_header[8];
  read_exact(cmd_header, 8);
  PortCommand cmd;
  std::size_t rest = static_cast<std::size_t>(total) - 8;
  std::size_t str_len = PortCommand::decode_header(cmd_header, rest, body_offset, cmd);
  if (str_len) {
    // The command string grows with the bytes that come, not with its announced length.
    struct Source {
      ReadExact& f;
      void read_exact(void* p, std::size_t n) { f(p, n); }
    } source{read_exact};
    std::vector<std::uint8_t> s;
    append_growing(source, s, str_len, nullptr);
    cmd.set_string(s.data(), s.size());
    rest -= str_len;
  }
  m.key = cmd.key;
  m.command = cmd.text.empty() ? std::string(1, cmd.key) : cmd.text;
  m.envelope = cmd.envelope();
  m.text_mode = false;
  m.reply_expected = cmd.key == 'd' || cmd.key == 'a';
  read_payload(rest, m);
}

}  // namespace robogene::carrier::detail
