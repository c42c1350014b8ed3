// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "binary_framing.hpp"

#include <cstdio>

#include "robogene/carrier/yarp_number.hpp"

namespace robogene::carrier::detail {

const std::uint8_t kAck[8] = {'Y', 'A', 0, 0, 0, 0, 'R', 'P'};

std::string hex_bytes(const std::uint8_t* data, std::size_t n) {
  std::string out;
  char b[4];
  for (std::size_t i = 0; i < n; ++i) {
    std::snprintf(b, sizeof b, i ? " %02x" : "%02x", data[i]);
    out += b;
  }
  return out;
}

void frame_message(const OutboundMessage& m, const EncodedPayload* payload,
                   std::vector<std::uint8_t>& head, std::vector<iovec>& iov) {
  PortCommand cmd;
  cmd.key = m.key;
  if (!m.envelope.empty() && (m.key == 'd' || m.key == 'D')) {
    cmd.text = std::string(1, m.key) + " " + m.envelope;
  } else if (m.key == 'q') {
    cmd.text = "q";  // YARP sends the disconnect as the ch-0 string "q"
  }
  std::size_t cmd_size = 8 + (cmd.text.empty() ? 0 : cmd.text.size() + 1);
  std::size_t payload_blocks = payload ? payload->block_count() : 0;
  // nIn is one byte; the receiver only uses the sum, so a payload with too many blocks is
  // announced as a single block.
  bool collapse = payload_blocks + 1 > 255;
  std::size_t n_in = 1 + (collapse ? 1 : payload_blocks);

  head.clear();
  Header idx = make_yarp_number(kIndexLength);
  head.insert(head.end(), idx.begin(), idx.end());
  head.push_back(static_cast<std::uint8_t>(n_in));
  head.push_back(1);
  head.insert(head.end(), 8, 0xff);
  std::size_t at = head.size();
  head.resize(at + 4 * (n_in + 1));
  put_int32(head.data() + at, static_cast<std::int32_t>(cmd_size));
  at += 4;
  if (collapse) {
    put_int32(head.data() + at, static_cast<std::int32_t>(payload->size()));
    at += 4;
  } else {
    for (std::size_t i = 0; i < payload_blocks; ++i, at += 4) {
      put_int32(head.data() + at, static_cast<std::int32_t>(payload->block_size(i)));
    }
  }
  put_int32(head.data() + at, 0);  // the "reply" slot, always 0
  cmd.encode(head);

  iov.clear();
  iov.push_back(iovec{head.data(), head.size()});
  if (payload) payload->append_iovecs(iov);
}

}  // namespace robogene::carrier::detail
