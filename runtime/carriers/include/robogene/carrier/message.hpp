// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Messages as the owner of a connection sees them, independent of the carrier.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "robogene/bottle.hpp"

namespace robogene::carrier {

// One message read from an inbound connection.
struct InboundMessage {
  // 'd' / 'D' data (with / without reply), 'a' admin, 'r' reverse, 'q' quit; text carriers also
  // deliver their line commands: '/', '!', '~', '*', '?', 'h' and anything else typed.
  char key = 0;
  std::string command;     // the whole command (ch-0 string or typed line, e.g. "do", "/out")
  std::string envelope;    // "1053 1795328338.10597" when the sender set one
  bool text_mode = false;  // payload holds bottle text (text carriers) rather than binary
  bool reply_expected = false;
  std::vector<std::uint8_t> payload;  // the bytes after the PortCommand (reused across reads)
  // Large blob bodies (binary carriers) are received straight into their own buffers instead of
  // `payload`, which then holds those blobs with length 0; `detached_blob_ordinals` says which
  // blobs (counted depth-first from 0) they are. Saves a copy of every image.
  std::vector<std::vector<std::uint8_t>> detached_blobs;
  std::vector<std::size_t> detached_blob_ordinals;
  // Buffers handed back by the owner once it is done with a Bottle (see recycle()), reused for
  // the next detached blobs so that a stream of images allocates and clears no new memory.
  std::vector<std::vector<std::uint8_t>> spare_blobs;

  // The payload as a Bottle, decoded from whichever form it has; throws ParseError.
  Bottle bottle(const DecodeLimits& limits = {}) const;
  // The same, moving detached blob bodies into the Bottle (no copy); the message is spent.
  Bottle take_bottle(const DecodeLimits& limits = {});
  // Takes back the large blob buffers of a Bottle that is no longer needed.
  void recycle(Bottle& b);
  std::string payload_text() const { return std::string(payload.begin(), payload.end()); }
};

// One message to send on an outbound connection.
struct OutboundMessage {
  char key = 'D';             // 'd' asks for a reply, 'D' does not; 'a', 'r', 'q'
  std::string envelope;       // sent as ch-0 "D <envelope>" when not empty
  const Bottle* bottle = nullptr;  // payload; must stay alive until send() returns
};

}  // namespace robogene::carrier
