// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// libFuzzer target: CAN frames as the head's boards send them, and candump log lines. The first
// byte picks the form:
//   even: a frame (11-bit id from two bytes, a length, up to 8 data bytes) into the
//         motor_control decoder. An accepted frame re-encodes, and decodes again to the same
//         message (decode(encode(decode(f))) == decode(f)); the re-encoded frame is a fixed
//         point; the text form reads back to the same message (from_text(to_text(e)) == e).
//   odd:  a line of a candump log (what `robogene can replay` reads). A parsed line formats
//         and parses back to the same entry.
// Anything else must end as CodecError / ParseError naming what is wrong.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "motor_control.hpp"
#include "robogene/can/candump_log.hpp"
#include "robogene/can/frame.hpp"
#include "robogene/error.hpp"

using namespace robogene;
using namespace robogene::can;

namespace {

void frame_properties(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return;
  Frame f;
  f.id = static_cast<std::uint16_t>((data[0] | (data[1] << 8)) & kMaxStandardId);
  f.len = static_cast<std::uint8_t>(data[2] % (kMaxDataLength + 1));
  for (std::size_t i = 0; i < f.len && 3 + i < size; ++i) f.data[i] = data[3 + i];
  Envelope e;
  try {
    e = decode(f);
  } catch (const CodecError&) {
    return;
  }
  Frame back;
  try {
    back = encode(e);
  } catch (const CodecError&) {
    __builtin_trap();  // the decoder accepted a message the encoder refuses
  }
  // Not back == f: padding bytes a message does not use are ignored on receipt and sent as 0.
  if (decode(back) != e) __builtin_trap();
  if (encode(decode(back)) != back) __builtin_trap();  // the canonical frame is a fixed point
  if (from_text(to_text(e)) != e) __builtin_trap();
}

void log_line_properties(const std::uint8_t* data, std::size_t size) {
  const std::string line(reinterpret_cast<const char*>(data), size);
  LogEntry entry;
  try {
    entry = parse_log_line(line);
  } catch (const Error&) {
    return;
  }
  const std::string text = format_log_line(entry);
  const LogEntry again = parse_log_line(text);
  if (format_log_line(again) != text) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  if (data[0] % 2 == 0) {
    frame_properties(data + 1, size - 1);
  } else {
    log_line_properties(data + 1, size - 1);
  }
  return 0;
}
