// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Probes a registration the way a polite YARP peer would: connect, send the tcp carrier header
// with the non-rooted sender name "admin" (ports do not log such connections), expect the
// "YA <port> RP" answer, then close with a proper 'q' message and wait for its ack.
// Refused, silent past the answer timeout, or answered but not like a port -> Dead. Accepted and
// hung up (a port at its limit of inputs), or an unreachable network -> Unknown.
#pragma once

#include "robogene/name/liveness.hpp"

namespace robogene::name {

class TcpLivenessProbe : public LivenessProbe {
 public:
  explicit TcpLivenessProbe(int connect_timeout_ms = 1000, int answer_timeout_ms = 2000)
      : connect_timeout_ms_(connect_timeout_ms), answer_timeout_ms_(answer_timeout_ms) {}
  Liveness probe(const Registration& r) override;

 private:
  int connect_timeout_ms_;
  int answer_timeout_ms_;
};

}  // namespace robogene::name
